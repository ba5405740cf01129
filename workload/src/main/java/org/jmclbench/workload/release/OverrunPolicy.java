package org.jmclbench.workload.release;

import java.util.concurrent.locks.LockSupport;

/**
 * What happens when an event is released while the robot (the one shared resource) is
 * busy: the strategy behind the skip, terminate and queue tests.
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
public abstract class OverrunPolicy {
    /** No event owns the robot. */
    static final int FREE = -1;

    private Thread[] handlers = new Thread[0];

    /** The thesis's test folder name for this policy (SkipTest, TermTest, QueueTest). */
    public abstract String testName();

    /** The command-line name (skip, terminate, queue). */
    public abstract String policyName();

    /** Called by the dispatcher at k's release; true hands k to its handler. */
    public abstract boolean admit(int k);

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

    /** A fresh policy (they hold per-replay state) by its command-line name. */
    public static OverrunPolicy forName(String name) {
        switch (name) {
            case "skip":
                return new SkipPolicy();
            case "terminate":
                return new TerminatePolicy();
            case "queue":
                return new QueuePolicy();
            default:
                throw new IllegalArgumentException("unknown policy: " + name);
        }
    }
}
