package org.jmclbench.rtsjcompat;

/**
 * What a thread waits on when it takes part in the {@link TimeSource}'s idle protocol (a
 * handler's {@link HandlerRuntime}, an RTSJ handler's {@link HandlerServer}, the sequencer's
 * {@link MissionControl}): the thread waits on this object's monitor with no deadline as an idle
 * participant, and whoever makes it runnable again ends the idleness under the same monitor,
 * before it wakes. The idle flag is guarded by this monitor, which every method's caller holds.
 * Allocation-free.
 */
abstract class IdleParticipant {
    /** The time source of the launch. */
    protected final TimeSource time;
    private boolean idle;

    IdleParticipant(TimeSource time) {
        this.time = time;
    }

    /**
     * Waits on this monitor as an idle participant of the time source. An interrupt ends the
     * wait like a notify: the caller's loop re-checks its own state.
     */
    protected final void idleWait() {
        if (!idle) {
            idle = true;
            time.enterIdle();
        }
        try {
            wait();
        } catch (InterruptedException e) {
            // Re-checked by the caller's loop.
        }
    }

    /** Makes the idle thread runnable and wakes it. */
    protected final void leaveIdle() {
        endIdle();
        notifyAll();
    }

    /** Ends the idleness without waking anyone (the thread itself, as it ends). */
    protected final void endIdle() {
        if (idle) {
            idle = false;
            time.leaveIdle();
        }
    }
}
