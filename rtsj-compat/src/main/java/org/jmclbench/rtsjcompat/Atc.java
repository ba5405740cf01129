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
 * each backward branch and after each call that returns into it, except inside a monitor region
 * or a {@code finally} (see the rtsj-weaver module). Code that is not rewritten (non-AI methods,
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
     */
    public static void poll() throws AsynchronouslyInterruptedException {
        if (PENDING.get() != 0) {
            deliver();
        }
    }

    private static void deliver() throws AsynchronouslyInterruptedException {
        Thread t = Thread.currentThread();
        if (t instanceof ScjThread) {
            AsynchronouslyInterruptedException p = ((ScjThread) t).atc.pending();
            if (p != null && p.isEnabled()) {
                throw p;
            }
        }
    }

    /**
     * Runs the ATC machinery {@code rounds} times on a thread of its own (an AIE fired at the
     * doInterruptible in progress, delivered at a poll, caught and cleared; a poll while an AIE is
     * pending on another thread), so that a JIT has
     * compiled it before a measured run fires its first AIE. An RTSJ VM's ATC is compiled VM
     * code; on HotSpot the rarely run fire and delivery paths would otherwise be interpreted, and
     * the never-taken delivery branch compiled as a trap that deoptimises at each first delivery
     * (measured in the rtsj engine: 5 to 24 us for one interpreted fire(), tens for a deoptimisation).
     * The job code is left as cold as the runtime leaves it. Call it before any schedulable runs.
     */
    public static void prime(final int rounds) {
        final AsynchronouslyInterruptedException aie = new AsynchronouslyInterruptedException();
        final Interruptible firesAtItself = new Interruptible() {
            @Override
            public void run(AsynchronouslyInterruptedException e) throws AsynchronouslyInterruptedException {
                e.fire();
                poll();
            }

            @Override
            public void interruptAction(AsynchronouslyInterruptedException e) {
            }
        };
        ScjThread t = new ScjThread(new Runnable() {
            @Override
            public void run() {
                for (int i = 0; i < rounds; i++) {
                    aie.doInterruptible(firesAtItself);
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
        }, "jmclbench-atc-prime", Thread.NORM_PRIORITY);
        t.start();
        if (ScjThread.joinThroughInterrupts(t)) {
            Thread.currentThread().interrupt();
        }
        if (PENDING.get() != 0) {
            throw new IllegalStateException("an AIE is still pending after priming the ATC");
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
