package org.jmclbench.rtsjcompat;

import java.util.concurrent.atomic.AtomicInteger;
import javax.realtime.AsynchronouslyInterruptedException;

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
     * Makes the delivery branch of {@link #poll()} look taken to the JIT. HotSpot compiles a
     * branch its profile never saw taken as a trap, and the first AIEs delivered through it then
     * each pay a deoptimisation (tens of microseconds, measured in the rtsj engine's abort latency)
     * that an RTSJ VM's ATC does not have. Polls here from a thread that is not a schedulable, so
     * nothing is thrown; call it before any schedulable runs.
     */
    public static void primeDelivery(int polls) {
        PENDING.incrementAndGet();
        try {
            for (int i = 0; i < polls; i++) {
                poll();
            }
        } catch (AsynchronouslyInterruptedException e) {
            throw new IllegalStateException("a delivery while priming: " + e);
        } finally {
            PENDING.decrementAndGet();
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
