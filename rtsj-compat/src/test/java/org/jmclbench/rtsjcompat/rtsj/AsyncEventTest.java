package org.jmclbench.rtsjcompat.rtsj;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTimeoutPreemptively;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Collections;
import java.util.List;
import java.util.concurrent.ArrayBlockingQueue;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.CountDownLatch;
import javax.realtime.AsyncEvent;
import javax.realtime.AsyncEventHandler;
import javax.realtime.BoundAsyncEventHandler;
import javax.realtime.PriorityParameters;
import org.jmclbench.rtsjcompat.RtsjRuntime;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

/** RTSJ release semantics: a fire count per handler, one handleAsyncEvent per fire, in order, on the handler's own thread. */
class AsyncEventTest {
    private static final Duration HANG = Duration.ofSeconds(60);

    @BeforeEach
    void fresh() {
        RtsjRuntime.reset();
    }

    @AfterEach
    void stop() {
        assertEquals(Collections.emptyList(), RtsjRuntime.stopHandlers(10000), "handlers still running");
    }

    /** A handler that takes one item per release from {@code items} and blocks on {@code gate} in its first release. */
    static final class Recorder extends BoundAsyncEventHandler {
        final List<Integer> handled = Collections.synchronizedList(new ArrayList<>());
        final List<Thread> threads = Collections.synchronizedList(new ArrayList<>());
        final BlockingQueue<Integer> items = new ArrayBlockingQueue<>(100);
        final CountDownLatch gate = new CountDownLatch(1);
        final CountDownLatch inFirst = new CountDownLatch(1);
        final int expected;
        final CountDownLatch done;
        volatile int pendingSeenInFirst = -1;

        Recorder(int expected) {
            super(new PriorityParameters(20), null, null, null, null, false, null);
            this.expected = expected;
            this.done = new CountDownLatch(expected);
        }

        @Override
        public void handleAsyncEvent() {
            threads.add(Thread.currentThread());
            if (handled.isEmpty() && inFirst.getCount() > 0) {
                inFirst.countDown();
                await(gate);
                pendingSeenInFirst = getPendingFireCount();
            }
            handled.add(items.poll());
            done.countDown();
        }
    }

    static void await(CountDownLatch l) {
        try {
            l.await();
        } catch (InterruptedException e) {
            throw new AssertionError(e);
        }
    }

    @Test
    void firesWhileTheHandlerRunsArePendingAndEachIsHandledOnceInOrder() {
        assertTimeoutPreemptively(HANG, () -> {
            AsyncEvent event = new AsyncEvent();
            Recorder h = new Recorder(5);
            event.addHandler(h);
            h.items.add(0);
            event.fire();
            await(h.inFirst);
            for (int k = 1; k < 5; k++) {
                h.items.add(k);
                event.fire();
            }
            assertEquals(4, h.getPendingFireCount());
            h.gate.countDown();
            await(h.done);
            assertEquals(Arrays.asList(0, 1, 2, 3, 4), h.handled);
            assertEquals(4, h.pendingSeenInFirst);
            assertEquals(0, h.getPendingFireCount());
            assertEquals(1, h.threads.stream().distinct().count(), "a bound handler runs on one thread");
            assertTrue(h.threads.get(0) != Thread.currentThread());
        });
    }

    @Test
    void everyAttachedHandlerIsReleasedByEachFireAndARemovedOneNoMore() {
        assertTimeoutPreemptively(HANG, () -> {
            AsyncEvent event = new AsyncEvent();
            CountDownLatch a = new CountDownLatch(2);
            CountDownLatch b = new CountDownLatch(1);
            AsyncEventHandler ha = new AsyncEventHandler(a::countDown);
            AsyncEventHandler hb = new AsyncEventHandler(b::countDown);
            event.addHandler(ha);
            event.addHandler(hb);
            event.addHandler(hb); // once only
            assertTrue(event.handledBy(ha) && event.handledBy(hb));
            event.fire();
            await(b);
            event.removeHandler(hb);
            event.fire();
            await(a);
            assertEquals(0, b.getCount());
            assertTrue(!event.handledBy(hb));
        });
    }

    @Test
    void aHandlerMayConsumeSeveralPendingFiresAtOnce() {
        assertTimeoutPreemptively(HANG, () -> {
            AsyncEvent event = new AsyncEvent();
            CountDownLatch gate = new CountDownLatch(1);
            CountDownLatch inFirst = new CountDownLatch(1);
            int[] releases = new int[1];
            int[] consumed = new int[1];
            CountDownLatch done = new CountDownLatch(1);
            AsyncEventHandler h = new AsyncEventHandler() {
                @Override
                public void handleAsyncEvent() {
                    releases[0]++;
                    inFirst.countDown();
                    await(gate);
                    consumed[0] += getAndClearPendingFireCount();
                    done.countDown();
                }
            };
            event.addHandler(h);
            event.fire();
            await(inFirst);
            event.fire();
            event.fire();
            event.fire();
            gate.countDown();
            await(done);
            assertEquals(Collections.emptyList(), RtsjRuntime.stopHandlers(10000));
            assertEquals(1, releases[0]);
            assertEquals(3, consumed[0]);
        });
    }

    @Test
    void anExceptionEscapingAHandlerIsRecordedAndTheHandlerServesOn() {
        assertTimeoutPreemptively(HANG, () -> {
            AsyncEvent event = new AsyncEvent();
            CountDownLatch second = new CountDownLatch(2);
            AsyncEventHandler h = new AsyncEventHandler(() -> {
                second.countDown();
                if (second.getCount() == 1) {
                    throw new IllegalStateException("job failed");
                }
            });
            event.addHandler(h);
            assertNull(RtsjRuntime.failure());
            event.fire();
            event.fire();
            await(second);
            assertNotNull(RtsjRuntime.failure());
            assertTrue(RtsjRuntime.failure().getMessage().contains("job failed"), RtsjRuntime.failure().getMessage());
            assertTrue(RtsjRuntime.failure().where().startsWith("AsyncEventHandler#"), RtsjRuntime.failure().where());
        });
    }

    @Test
    void aHandlerThatNeverEndsIsNamedByStopHandlers() {
        AsyncEvent event = new AsyncEvent();
        CountDownLatch never = new CountDownLatch(1);
        CountDownLatch started = new CountDownLatch(1);
        AsyncEventHandler h = new AsyncEventHandler(() -> {
            started.countDown();
            await(never);
        });
        event.addHandler(h);
        event.fire();
        await(started);
        List<String> alive = RtsjRuntime.stopHandlers(50);
        assertEquals(1, alive.size());
        assertTrue(alive.get(0).startsWith("AsyncEventHandler#"), alive.toString());
        never.countDown();
    }
}
