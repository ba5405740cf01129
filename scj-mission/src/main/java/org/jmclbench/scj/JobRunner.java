package org.jmclbench.scj;

import javax.realtime.AbsoluteTime;

import org.jmclbench.core.mcl.AbortSignal;
import org.jmclbench.core.record.JobRecords;

/**
 * One handler's side of a job: records the event's release, runs the job on the robot (holding
 * its monitor, so the start is when the robot became this job's), records start, end and
 * outcome, and counts the event as ended, the last one requesting the mission's termination.
 * Also the job's abort signal, and where the handler's release ends. One per handler, used by
 * that handler's thread only; no allocation.
 */
final class JobRunner implements AbortSignal {
    private final Robot robot;
    private final JobGate gate;
    private final ImmortalEntry entry;
    private final MissionClock clock;
    private final MclMission mission;
    private final MissionOutput output;
    private final int area;
    private final AbsoluteTime now = new AbsoluteTime();
    private final AbsoluteTime pollTime = new AbsoluteTime();
    private int event = JobGate.FREE;
    // when the gate stops the job whatever the polls say (JobGate.periodicAbortAtNs); MAX_VALUE: never
    private long abortAtNs = Long.MAX_VALUE;

    /** {@code area}: the private memory of the handler this runner serves ({@link MissionSizes}). */
    JobRunner(Robot robot, JobGate gate, ImmortalEntry entry, MissionClock clock, MclMission mission,
            MissionOutput output, int area) {
        this.robot = robot;
        this.gate = gate;
        this.entry = entry;
        this.clock = clock;
        this.mission = mission;
        this.output = output;
        this.area = area;
    }

    // when a poll of this job first answered true, ns from the mission start; -1 not yet
    private long seenNs = -1;

    @Override
    public boolean abortRequested() {
        boolean requested = gate.abortRequested(event);
        if (!requested && abortAtNs == Long.MAX_VALUE) {
            return false;
        }
        // One clock read for both reasons. A periodic job reads it at every poll, so a JIT compiles
        // this call inline; a call site of its own for the gate's request would stay a cold call,
        // which HotSpot resolves at each loop's first abort (tens of us, counted as noticing).
        long now = clock.nowNs(pollTime);
        if (!requested && now < abortAtNs) {
            return false;
        }
        if (seenNs < 0) {
            seenNs = now;
        }
        return true;
    }

    /** Now, ns from the mission start. */
    long nowNs() {
        return clock.nowNs(now);
    }

    /** Records event k's release: its scheduled time and deadline, and when its handler woke for it. */
    void released(int k, long wakeNs) {
        JobRecords r = entry.records;
        r.releaseNs[k] = entry.releaseNs[k];
        r.deadlineNs[k] = entry.deadlineNs[k];
        r.wakeNs[k] = wakeNs;
    }

    /** Event k was dropped at its release. */
    void skip(int k) {
        entry.records.outcome[k] = JobRecords.SKIPPED;
        ended();
    }

    /**
     * Runs k's job; {@code abortAtNs} is when the gate stops it whatever the polls say
     * (Long.MAX_VALUE: never). A job whose abort was asked while it waited for the robot never
     * starts (terminated, start and end -1), as in the other engines. Returns the job's end, ns
     * from the mission start.
     */
    long run(int k, boolean update, long abortAtNs) {
        event = k;
        this.abortAtNs = abortAtNs;
        seenNs = -1;
        long start = -1;
        long end;
        boolean completed = false;
        synchronized (robot) {
            if (!gate.mayStart(k) || abortRequested()) {
                end = nowNs(); // superseded before it had the robot
            } else {
                start = nowNs();
                completed = update ? robot.update(k, this) : robot.predict(k, this);
                end = nowNs();
            }
        }
        if (!update) {
            gate.periodicEnded(end); // before the robot is free: a sensor deciding a tie next sees an overrun
        }
        gate.release(k);
        if (abortAtNs < end) {
            gate.periodicAbortRequested(k, abortAtNs);
        }
        JobRecords r = entry.records;
        r.cpuNs[k] = -1; // SCJ has no per-thread CPU clock
        if (start < 0) {
            r.startNs[k] = -1;
            r.endNs[k] = -1;
            r.outcome[k] = JobRecords.TERMINATED;
            ended();
            return end;
        }
        r.startNs[k] = start;
        r.endNs[k] = end;
        if (seenNs >= 0) {
            r.abortSeen(k, seenNs);
        }
        if (!completed) {
            r.outcome[k] = JobRecords.TERMINATED;
        } else {
            r.outcome[k] = end <= r.deadlineNs[k] ? JobRecords.DONE : JobRecords.LATE;
        }
        ended();
        return end;
    }

    /** The handler's release is ending: the output may measure its private memory. */
    void releaseEnding() {
        output.releaseEnding(area);
    }

    private void ended() {
        if (gate.ended()) {
            mission.allEventsEnded(gate.endedCount());
        }
    }
}
