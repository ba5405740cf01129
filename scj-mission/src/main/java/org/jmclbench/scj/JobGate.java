package org.jmclbench.scj;

import org.jmclbench.core.policy.OverrunPolicy;
import org.jmclbench.core.record.JobRecords;
import org.jmclbench.core.timeline.Timeline;

/**
 * The mission's side of the overrun policy, shared by the handlers: it asks the policy's rule
 * ({@link OverrunPolicy}, whose state it keeps and changes only under its monitor) which event
 * may use the robot and which job must abort, decides the events of one instant together, and
 * counts the events that have ended (so that the last one ends the mission). The handlers report
 * facts (a release, its time, a job's end); no decision of a policy is taken here or in them.
 *
 * <p>Protocol per merged event k: at its release, {@link #admit(int)}, or for the periodic task
 * {@link #admitPeriodic(int, long)} (false: k is skipped); its job polls
 * {@link #abortRequested(int)} and, periodic, also stops at {@link #periodicAbortAtNs(long)};
 * when the job has ended, {@link #release(int)} (periodic: after {@link #periodicEnded(long)});
 * and exactly once per event, whatever its outcome, {@link #ended()}. Allocation-free; no
 * wait/notify (SCJ Level 1): a job waits for the robot only on the robot's monitor.
 *
 * <p>Events at the same time ({@link #orderTies(Timeline, long[])}) are decided together, in timeline
 * order, at the first of their releases, whichever handler brings it: the periodic handler and the
 * sensor wake in an order of their own, and the other engines' dispatcher decides such events in
 * timeline order before any starts (docs/RELEASE-ENGINE.md, "Events at the same time"). Under
 * skip, the periodic task's previous job overrunning the instant's scheduled release drops the
 * whole instant whichever handler decides it, also a sensor that arrives after that job ended.
 * Not final: a verification test may replace it (see {@link MissionConfiguration#newGate}).
 */
public class JobGate {
    /** No event holds the robot. */
    public static final int FREE = -1;

    private static final byte UNDECIDED = 0;
    private static final byte ADMITTED = 1;
    private static final byte DROPPED = 2;

    private final OverrunPolicy policy;
    // the policy's state (skip's reservation, terminate's latest event); changed under this monitor
    private final OverrunPolicy.State rule;
    private final int events;
    // each event's admission, taken once (for the events of one time, at the first release of them)
    private final byte[] decision;
    // the merged timeline, whose events at equal times are decided together; null: each alone
    private Timeline timeline;
    // each event's scheduled release, ns from the mission start (with the timeline)
    private long[] releaseNs;
    private int ended;
    // when the periodic task's previous job ended, ns from the mission start; written by that
    // task's handler before its job frees the robot, read by whichever handler decides an instant
    private long periodicEndNs = Long.MIN_VALUE;
    // where abort requests are recorded (JobRecords.abortNs); null, not recorded
    private JobRecords records;

    /** Unordered: the robot's monitor, not the rule, orders the jobs that wait for it (no wait/notify). */
    public JobGate(OverrunPolicy policy, int events) {
        this.policy = policy;
        this.rule = new OverrunPolicy.State(policy, false);
        this.events = events;
        this.decision = new byte[Math.max(0, events)];
    }

    /**
     * Events at equal times in {@code t} (the mission's merged timeline) are decided together, in its
     * order, as at their scheduled release {@code releaseNs[k]} (ns from the mission start).
     */
    public synchronized void orderTies(Timeline t, long[] releaseNs) {
        timeline = t;
        this.releaseNs = releaseNs;
    }

    /** The policy. */
    public OverrunPolicy policy() {
        return policy;
    }

    /**
     * Records abort requests in {@code r} (terminate's): the job of the event a release supersedes is
     * asked to abort at that release's wake-up ({@code r.wakeNs}, set before {@link #admit(int)}),
     * a periodic job at its task's next release ({@link #periodicAbortRequested(int, long)}).
     */
    public synchronized void recordAbortsIn(JobRecords r) {
        records = r;
    }

    /**
     * At k's release: true hands k to its handler, false drops it (the policy's rule). The first
     * release of an instant decides every event of that time, in timeline order.
     */
    public synchronized boolean admit(int k) {
        return admitAt(k, false);
    }

    /**
     * k's decision, taking those of its instant's events not yet decided; {@code busy}: the robot
     * was busy at that instant whatever the rule's state says (skip drops them all).
     */
    private synchronized boolean admitAt(int k, boolean busy) {
        if (decision[k] == UNDECIDED) {
            int first = k;
            int last = k;
            if (timeline != null) {
                double t = timeline.time(k);
                while (first > 0 && timeline.time(first - 1) == t) {
                    first--;
                }
                while (last + 1 < timeline.size() && timeline.time(last + 1) == t) {
                    last++;
                }
                // The periodic release of this instant, if any, judged as admitPeriodic judges it: the
                // sensor may decide the instant after the task's overrunning job freed the robot.
                for (int j = first; j <= last; j++) {
                    busy |= timeline.task(j) == Timeline.PREDICT && overran(releaseNs[j]);
                }
            }
            long requestNs = records != null ? records.wakeNs[k] : -1; // the release that decides
            for (int j = first; j <= last; j++) {
                if (decision[j] == UNDECIDED) {
                    decision[j] = decide(j, busy, requestNs) ? ADMITTED : DROPPED;
                }
            }
        }
        // Through a local: the icecap HVM's compiler (compiled mode) read a synchronized method's
        // result left on the operand stack after the monitor exit, whose call reuses that stack,
        // and handed the sensor 16 for a dropped event (docs/HVM.md, "Known compiler defects").
        boolean admitted = decision[k] == ADMITTED;
        return admitted;
    }

    /**
     * The policy's decision for event j, released at {@code requestNs}, and the abort request of the
     * event it supersedes. Synchronized although only {@link #admitAt} calls it (re-entering the
     * monitor it holds): the static P2 rule wants every change of the rule's state and every access
     * to {@code records} under the gate's monitor.
     */
    private synchronized boolean decide(int j, boolean busy, long requestNs) {
        if (!rule.admit(j, busy)) {
            return false;
        }
        int superseded = rule.superseded();
        if (superseded != FREE && records != null) {
            records.requestAbort(superseded, requestNs);
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
     * with the robot judged busy when the task's own previous job ended after that time (it
     * overran into this release); skip then drops it.
     */
    public boolean admitPeriodic(int k, long releaseNs) {
        return admitAt(k, overran(releaseNs));
    }

    /** The periodic task's previous job ended after {@code releaseNs}, so it held the robot then. */
    private synchronized boolean overran(long releaseNs) {
        boolean overran = periodicEndNs > releaseNs; // through a local: see admitAt
        return overran;
    }

    /**
     * When a periodic job must stop whatever the polls say, given its task's next release
     * ({@code Long.MAX_VALUE}: none): a policy whose release aborts the job in progress
     * (terminate) aborts it at that release, as a sensor release aborts an update (the periodic
     * handler is not released while its job runs); {@code Long.MAX_VALUE} (never) under the others.
     */
    public long periodicAbortAtNs(long nextReleaseNs) {
        return policy.abortsJobInProgress() ? nextReleaseNs : Long.MAX_VALUE;
    }

    /**
     * The periodic task's job ended at {@code endNs} (ns from the mission start), completed or not;
     * called before its {@link #release(int)}, so that no handler sees the robot free without it.
     */
    public synchronized void periodicEnded(long endNs) {
        periodicEndNs = endNs;
    }

    /**
     * Whether k's job, holding the robot's monitor, may start (false: superseded before it started,
     * it never starts). Lock-free, as the poll: the rule reads only volatile fields here.
     */
    public boolean mayStart(int k) {
        return policy.start(rule, k) != OverrunPolicy.NEVER;
    }

    /** Polled by k's job: true asks it to stop and leave the robot unchanged (the policy's rule). Lock-free. */
    public boolean abortRequested(int k) {
        return policy.abortRequested(rule, k);
    }

    /** k's job has ended, completed or not (or never started): the rule may free the robot (skip). */
    public synchronized void release(int k) {
        rule.ended(k);
    }

    /** Counts one ended event (done, late, skipped or terminated); true for the last of them. */
    public synchronized boolean ended() {
        ended++;
        boolean last = ended == events; // through a local: see admitAt
        return last;
    }

    /** The number of events ended so far. */
    public synchronized int endedCount() {
        return ended;
    }
}
