package org.jmclbench.workload.release;

import java.util.concurrent.locks.LockSupport;

import org.jmclbench.core.policy.OverrunPolicy;

/**
 * The Java SE engine's state of an {@link OverrunPolicy}: what happens when an event is
 * released while the robot (the one shared resource) is busy, for the skip, terminate and
 * queue tests. One gate per replay: it holds that replay's state.
 *
 * <p>Protocol, per event k in release order (k ascending):
 * <ol>
 *   <li>the dispatcher calls {@link #admit(int)} at k's release; false drops k (skipped);</li>
 *   <li>k's handler calls {@link #acquire(int)} before it starts the job; it blocks until k
 *       may use the robot, and returns false when k was superseded before it started;</li>
 *   <li>the job polls {@link #abortRequested(int)};</li>
 *   <li>the handler calls {@link #release(int)} when the job has ended, completed or not.</li>
 * </ol>
 * Every method is allocation-free; waiting handlers park and are unparked by {@link #release}.
 */
public abstract class PolicyGate {
    /** No event owns the robot. */
    static final int FREE = -1;

    private Thread[] handlers = new Thread[0];

    /** Called by the dispatcher at k's release; true hands k to its handler. */
    public abstract boolean admit(int k);

    /**
     * After {@link #admit(int)}: the event whose job that release asked to abort (terminate: the
     * previous latest, running, about to run or already ended), or FREE; dispatcher thread only.
     */
    public int superseded() {
        return FREE;
    }

    /** Called by k's handler before starting; false means k must not start (terminated). */
    public abstract boolean acquire(int k);

    /** Polled by k's job: true asks it to stop and leave the robot unchanged. */
    public abstract boolean abortRequested(int k);

    /** Called by k's handler when its job has ended (completed or aborted). */
    public abstract void release(int k);

    /** The handler threads, so that a release can wake a handler waiting for the robot. */
    final void handlerThreads(Thread[] threads) {
        this.handlers = threads.clone();
    }

    /** Wakes every handler but the caller; spurious wake-ups are re-checked by the waiter. */
    final void wakeOtherHandlers() {
        Thread self = Thread.currentThread();
        for (Thread t : handlers) {
            if (t != self) {
                LockSupport.unpark(t);
            }
        }
    }

    /** A fresh gate (it holds one replay's state) of the policy. */
    public static PolicyGate of(OverrunPolicy policy) {
        switch (policy) {
            case SKIP:
                return new SkipGate();
            case TERMINATE:
                return new TerminateGate();
            case QUEUE:
                return new QueueGate();
            default:
                throw new IllegalArgumentException("no gate for the policy " + policy);
        }
    }
}
