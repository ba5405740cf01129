package org.jmclbench.workload.release;

import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.locks.LockSupport;

import org.jmclbench.core.policy.OverrunPolicy;

/**
 * The Java SE engine's mechanics of an {@link OverrunPolicy}: the policy's rule decides (admit or
 * drop, whose abort, may a job start), this gate holds the robot (a CAS) and parks a handler the
 * rule tells to wait. One gate per replay: it holds that replay's state, ordered (queue hands the
 * robot over in release order, a ticket: event k after k - 1 has ended).
 *
 * <p>Protocol, per event k in release order (k ascending):
 * <ol>
 *   <li>the dispatcher calls {@link #admit(int)} at k's release; false drops k (skipped);</li>
 *   <li>k's handler calls {@link #acquire(int)} before it starts the job; it blocks until k
 *       may use the robot, and returns false when k was superseded before it started;</li>
 *   <li>the job polls {@link #abortRequested(int)};</li>
 *   <li>the handler calls {@link #release(int)} when the job has ended, completed or not.</li>
 * </ol>
 * Lock-free and allocation-free: the rule's state is changed by the dispatcher (admit) and by
 * k's handler (its end) only, through volatile fields; waiting handlers park and are unparked by
 * {@link #release}.
 */
public final class PolicyGate {
    /** No event owns the robot. */
    static final int FREE = OverrunPolicy.State.FREE;

    private final OverrunPolicy policy;
    private final OverrunPolicy.State rule;
    /** The event whose job holds the robot, or FREE. */
    private final AtomicInteger robot = new AtomicInteger(FREE);
    private Thread[] handlers = new Thread[0];

    private PolicyGate(OverrunPolicy policy) {
        this.policy = policy;
        this.rule = new OverrunPolicy.State(policy, true);
    }

    /** A fresh gate (it holds one replay's state) of the policy. */
    public static PolicyGate of(OverrunPolicy policy) {
        return new PolicyGate(policy);
    }

    /** Called by the dispatcher at k's release; true hands k to its handler. */
    public boolean admit(int k) {
        return rule.admit(k, false);
    }

    /**
     * After {@link #admit(int)}: the event whose job that release asked to abort (terminate: the
     * previous latest, running, about to run or already ended), or FREE; dispatcher thread only.
     */
    public int superseded() {
        return rule.superseded();
    }

    /** Called by k's handler before starting; false means k must not start (terminated). */
    public boolean acquire(int k) {
        while (true) {
            int start = policy.start(rule, k);
            if (start == OverrunPolicy.NEVER || (start == OverrunPolicy.START && policy.abortRequested(rule, k))) {
                return false;
            }
            if (start == OverrunPolicy.START && robot.compareAndSet(FREE, k)) {
                return true;
            }
            // Not our turn, or the previous job is still unwinding: its release unparks us.
            LockSupport.park();
        }
    }

    /** Polled by k's job: true asks it to stop and leave the robot unchanged. */
    public boolean abortRequested(int k) {
        return policy.abortRequested(rule, k);
    }

    /** Called by k's handler when its job has ended (completed or aborted). */
    public void release(int k) {
        robot.set(FREE);
        rule.ended(k);
        if (policy.eventsWait()) {
            wakeOtherHandlers();
        }
    }

    /** The handler threads, so that a release can wake a handler waiting for the robot. */
    void handlerThreads(Thread[] threads) {
        this.handlers = threads.clone();
    }

    /** Wakes every handler but the caller; spurious wake-ups are re-checked by the waiter. */
    private void wakeOtherHandlers() {
        Thread self = Thread.currentThread();
        for (Thread t : handlers) {
            if (t != self) {
                LockSupport.unpark(t);
            }
        }
    }
}
