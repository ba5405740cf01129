package org.jmclbench.scj;

import org.jmclbench.core.policy.OverrunPolicy;
import org.jmclbench.core.record.JobRecords;

/**
 * The overrun policy's whole rule and state, shared by the handlers: which event may use the
 * robot, which job must abort, and how many events have ended (so that the last one ends the
 * mission). The handlers report facts (a release, its time, a job's end); every decision of
 * skip, terminate and queue is taken here.
 *
 * <p>Protocol per merged event k: at its release, {@link #admit(int)}, or for the periodic task
 * {@link #admitPeriodic(int, long)} (false: k is skipped); its job polls
 * {@link #abortRequested(int)} and, periodic, also stops at {@link #periodicAbortAtNs(long)};
 * when the job has ended, {@link #release(int)} (periodic: also {@link #periodicEnded(long)});
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
    // skip: when the periodic task's previous job ended, ns from the mission start; written and
    // read by that task's handler only, so it needs no lock
    private long periodicEndNs = Long.MIN_VALUE;
    // terminate: where abort requests are recorded (JobRecords.abortNs); null, not recorded
    private JobRecords records;

    public JobGate(OverrunPolicy policy, int events) {
        this.policy = policy;
        this.events = events;
    }

    /** The policy. */
    public OverrunPolicy policy() {
        return policy;
    }

    /**
     * Records terminate's abort requests in {@code r}: the job of the event a release supersedes is
     * asked to abort at that release's wake-up ({@code r.wakeNs}, set before {@link #admit(int)}),
     * a periodic job at its task's next release ({@link #periodicAbortRequested(int, long)}).
     */
    public synchronized void recordAbortsIn(JobRecords r) {
        records = r;
    }

    /** At k's release: true hands k to its handler, false drops it (skip, the robot busy). */
    public synchronized boolean admit(int k) {
        if (policy == OverrunPolicy.SKIP) {
            if (owner != FREE) {
                return false;
            }
            owner = k;
        } else if (policy == OverrunPolicy.TERMINATE) {
            int superseded = latest;
            latest = k; // the job in progress sees this at its next poll and aborts
            if (superseded != FREE && records != null) {
                records.requestAbort(superseded, records.wakeNs[k]);
            }
        }
        return true;
    }

    /**
     * The periodic job of k ran past {@code atNs}, its {@link #periodicAbortAtNs(long)}: its abort
     * was requested then (unless a release asked earlier).
     */
    public synchronized void periodicAbortRequested(int k, long atNs) {
        if (records != null) {
            records.requestAbort(k, atNs);
        }
    }

    /**
     * At the periodic task's release of k, scheduled at {@code releaseNs}: as {@link #admit(int)},
     * and under skip also dropped when the task's own previous job ended after that time (it
     * overran into this release: the robot was busy with it).
     */
    public boolean admitPeriodic(int k, long releaseNs) {
        if (policy == OverrunPolicy.SKIP && periodicEndNs > releaseNs) {
            return false;
        }
        return admit(k);
    }

    /**
     * When a periodic job must stop whatever the polls say, given its task's next release
     * ({@code Long.MAX_VALUE}: none): terminate aborts it at that release, as a sensor release
     * aborts an update; {@code Long.MAX_VALUE} (never) under the other policies.
     */
    public long periodicAbortAtNs(long nextReleaseNs) {
        return policy == OverrunPolicy.TERMINATE ? nextReleaseNs : Long.MAX_VALUE;
    }

    /** The periodic task's job ended at {@code endNs} (ns from the mission start), completed or not. */
    public void periodicEnded(long endNs) {
        periodicEndNs = endNs;
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
