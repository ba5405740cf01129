package org.jmclbench.scj;

/**
 * The overrun policy's state, shared by the handlers: which event may use the robot, which job
 * must abort, and how many events have ended (so that the last one ends the mission).
 *
 * <p>Protocol per merged event k: at its release, {@link #admit(int)} (false: k is skipped);
 * its job polls {@link #abortRequested(int)}; when the job has ended, {@link #release(int)};
 * and exactly once per event, whatever its outcome, {@link #ended()}. Allocation-free; no
 * wait/notify (SCJ Level 1): a job waits for the robot only on the robot's monitor.
 * Not final: a verification test may replace it (see {@link MissionConfiguration#newGate}).
 */
public class JobGate {
    /** No event holds the robot. */
    public static final int FREE = -1;

    private final OverrunPolicy policy;
    private final int events;
    // skip: the event whose job holds (or, released but not started, has reserved) the robot
    private int owner = FREE;
    // terminate: the latest released event, the only one allowed to run; read by the polls
    private volatile int latest = FREE;
    private int ended;

    public JobGate(OverrunPolicy policy, int events) {
        this.policy = policy;
        this.events = events;
    }

    /** The policy. */
    public OverrunPolicy policy() {
        return policy;
    }

    /** At k's release: true hands k to its handler, false drops it (skip, the robot busy). */
    public synchronized boolean admit(int k) {
        if (policy == OverrunPolicy.SKIP) {
            if (owner != FREE) {
                return false;
            }
            owner = k;
        } else if (policy == OverrunPolicy.TERMINATE) {
            latest = k; // the job in progress sees this at its next poll and aborts
        }
        return true;
    }

    /** Polled by k's job: true asks it to stop and leave the robot unchanged (terminate only). */
    public boolean abortRequested(int k) {
        return policy == OverrunPolicy.TERMINATE && latest != k;
    }

    /** k's job has ended, completed or not: the robot is free again (skip). */
    public synchronized void release(int k) {
        if (owner == k) {
            owner = FREE;
        }
    }

    /** Counts one ended event (done, late, skipped or terminated); true for the last of them. */
    public synchronized boolean ended() {
        ended++;
        return ended == events;
    }

    /** The number of events ended so far. */
    public synchronized int endedCount() {
        return ended;
    }
}
