package org.jmclbench.rtsjcompat;

import java.util.concurrent.atomic.AtomicInteger;

import javax.realtime.AsynchronouslyInterruptedException;
import javax.realtime.Interruptible;

/**
 * The runtime side of asynchronous transfer of control on a stock JVM: the delivery point.
 *
 * <p>A JVM cannot throw into another thread at an arbitrary instruction without
 * {@code Thread.stop}; so the build rewrites every AI-enabled method (one declaring
 * {@code throws AsynchronouslyInterruptedException}) to call {@link #poll()} at its entry, at
 * each backward branch, after each call that returns into it and where a monitor region or a
 * {@code finally} ends, except inside a monitor region or a {@code finally} (see the rtsj-weaver
 * module). Code that is not rewritten (non-AI methods,
 * libraries) has no delivery point, which is exactly RTSJ's deferral: a fired AIE stays pending
 * until control is back in AI-enabled code.
 *
 * <p>{@link #poll()} costs one volatile read while no AIE is pending anywhere in the JVM.
 */
public final class Atc {
    private static final AtomicInteger PENDING = new AtomicInteger();

    private Atc() {
    }

    /**
     * A delivery point: throws the AIE pending on the calling thread if it is enabled, else
     * returns. Allocates nothing (the AIE is the fired object itself, without a stack trace).
     * It calls nothing but accessors on its way to the throw: a JIT inlines it into every loop of
     * AI-enabled code, where the throw path is cold, and HotSpot resolves a cold call there at
     * that loop's first delivery (measured 20 to 34 us in the rtsj engine).
     */
    public static void poll() throws AsynchronouslyInterruptedException {
        if (PENDING.get() != 0) {
            Thread t = Thread.currentThread();
            if (t instanceof ScjThread) {
                AsynchronouslyInterruptedException p = ((ScjThread) t).atc.deliverable();
                if (p != null) {
                    throw p;
                }
            }
        }
    }

    /**
     * Runs the ATC machinery {@code rounds} times (an AIE fired at the doInterruptible in
     * progress, delivered at a poll, caught and cleared; a poll while an AIE is pending on another
     * thread), so that a JIT has compiled it before a measured run fires its first AIE. An RTSJ
     * VM's ATC is compiled VM code; on HotSpot the rarely run fire and delivery paths would
     * otherwise be interpreted, and the never-taken delivery branch compiled as a trap that
     * deoptimises at each first delivery (measured in the rtsj engine: 5 to 24 us for one
     * interpreted fire(), tens for a deoptimisation).
     *
     * <p>The rounds run on threads of three classes with three {@code Interruptible} classes, so
     * that the type checks on the way (the thread at a delivery point, the logic that
     * doInterruptible runs) are compiled for any class. With one class, HotSpot compiles a
     * check for that class and deoptimises when a schedulable of another class takes its
     * first AIE. bench/atc-latency.sh measured the difference.
     *
     * <p>Call it before any schedulable runs and before the job code is compiled. Job code compiled
     * earlier saw a delivery branch never taken, and deoptimises at its first delivery. The job
     * code itself is left as cold as the runtime leaves it.
     */
    public static void prime(int rounds) {
        AsynchronouslyInterruptedException aie = new AsynchronouslyInterruptedException();
        Interruptible[] logics = {new FiresAtItself(), new FiresAtItself() { }, new FiresAtItself() { }};
        Runnable body = primingRounds(aie, logics, Math.max(1, rounds / 3));
        // three thread classes: ScjThread and two anonymous subclasses of it
        ScjThread[] threads = {new ScjThread(body, "jmclbench-atc-prime-0", Thread.NORM_PRIORITY),
            new ScjThread(body, "jmclbench-atc-prime-1", Thread.NORM_PRIORITY) { },
            new ScjThread(body, "jmclbench-atc-prime-2", Thread.NORM_PRIORITY) { }};
        boolean interrupted = false;
        for (ScjThread t : threads) {
            t.start();
            interrupted |= ScjThread.joinThroughInterrupts(t);
        }
        if (interrupted) {
            Thread.currentThread().interrupt();
        }
        if (PENDING.get() != 0) {
            throw new IllegalStateException("an AIE is still pending after priming the ATC");
        }
    }

    /** One priming thread's work: {@code rounds} deliveries, the logics taken in turn, then polls. */
    private static Runnable primingRounds(final AsynchronouslyInterruptedException aie, final Interruptible[] logics,
            final int rounds) {
        return new Runnable() {
            @Override
            public void run() {
                for (int i = 0; i < rounds; i++) {
                    aie.doInterruptible(logics[i % logics.length]);
                }
                // and a poll while an AIE is pending on another thread only: it returns
                PENDING.incrementAndGet();
                try {
                    for (int i = 0; i < rounds; i++) {
                        poll();
                    }
                } catch (AsynchronouslyInterruptedException e) {
                    throw new IllegalStateException("an AIE delivered where none was pending", e);
                } finally {
                    PENDING.decrementAndGet();
                }
            }
        };
    }

    /** Priming logic: fires its own AIE and polls, so that the AIE is delivered at once. */
    private static class FiresAtItself implements Interruptible {
        @Override
        public void run(AsynchronouslyInterruptedException e) throws AsynchronouslyInterruptedException {
            e.fire();
            poll();
        }

        @Override
        public void interruptAction(AsynchronouslyInterruptedException e) {
        }
    }

    /** How many threads have an AIE pending (for tests). */
    public static int pendingThreads() {
        return PENDING.get();
    }

    static void pendingChanged(int delta) {
        PENDING.addAndGet(delta);
    }
}
