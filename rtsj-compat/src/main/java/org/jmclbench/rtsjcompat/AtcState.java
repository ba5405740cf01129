package org.jmclbench.rtsjcompat;

import javax.realtime.AsynchronouslyInterruptedException;

/**
 * One schedulable thread's side of asynchronous transfer of control (RTSJ chapter 8): how many
 * {@code doInterruptible} calls are in progress on it and which AIE is pending on it, if any.
 *
 * <p>Pending rule (RTSJ 1.0.2): a fired AIE replaces the pending one only if its
 * {@code doInterruptible} is further out (it would unwind the inner one anyway); the generic AIE
 * (depth -1) is outermost of all. Whether an AIE is pending anywhere is also counted globally,
 * so that a delivery point ({@link Atc#poll()}) costs one volatile read while nothing is
 * pending. Allocation-free; fire comes from other threads, so the state is guarded by this
 * object's monitor, and {@link #deliverable()} is a volatile read for the delivery points.
 */
public final class AtcState {
    private final Thread owner;
    private volatile AsynchronouslyInterruptedException pending;
    // The pending AIE while it is enabled, else null: what a delivery point throws. Kept here so
    // that the delivery point calls no method of the AIE: HotSpot's C2 never inlines a method of
    // an exception class into other code, and such a call, compiled into every job loop and
    // first run at that loop's first delivery, was measured costing 20 to 34 us there.
    private volatile AsynchronouslyInterruptedException deliverable;
    private int pendingDepth;
    private int depth;

    AtcState(Thread owner) {
        this.owner = owner;
    }

    /** The thread this state belongs to. */
    public Thread owner() {
        return owner;
    }

    /** The calling thread's state, or null when it is not a schedulable thread of this layer. */
    public static AtcState current() {
        Thread t = Thread.currentThread();
        return t instanceof ScjThread ? ((ScjThread) t).atc : null;
    }

    /** The AIE pending on this thread, or null. */
    public AsynchronouslyInterruptedException pending() {
        return pending;
    }

    /** The AIE to throw at a delivery point on this thread: the pending one if enabled, else null. */
    public AsynchronouslyInterruptedException deliverable() {
        return deliverable;
    }

    /**
     * {@code aie}'s enabled state changed: whether it is deliverable follows. Called by its owner
     * thread after the change, so its next delivery point sees the new state.
     */
    public synchronized void enabledChanged(AsynchronouslyInterruptedException aie) {
        if (pending == aie) {
            deliverable = aie.isEnabled() ? aie : null;
        }
    }

    /** How many doInterruptible calls are in progress here. */
    public synchronized int depth() {
        return depth;
    }

    /** A doInterruptible begins here; returns its depth (0 outermost). */
    public synchronized int enter() {
        return depth++;
    }

    /** The innermost doInterruptible ends. */
    public synchronized void exit() {
        depth--;
    }

    /**
     * Makes {@code aie}, whose doInterruptible runs at {@code aieDepth} here (-1: the generic
     * AIE), pending unless one further out already is. True when aie is pending afterwards.
     */
    public synchronized boolean makePending(AsynchronouslyInterruptedException aie, int aieDepth) {
        AsynchronouslyInterruptedException p = pending;
        if (p == null) {
            Atc.pendingChanged(1);
        } else if (p == aie || aieDepth >= pendingDepth) {
            return p == aie;
        }
        pending = aie;
        pendingDepth = aieDepth;
        deliverable = aie.isEnabled() ? aie : null;
        return true;
    }

    /** Clears {@code aie} if it is the pending one; true when it was. */
    public synchronized boolean clear(AsynchronouslyInterruptedException aie) {
        if (aie == null || pending != aie) {
            return false;
        }
        pending = null;
        deliverable = null;
        Atc.pendingChanged(-1);
        return true;
    }
}
