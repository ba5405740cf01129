package org.jmclbench.workload.release;

import org.jmclbench.core.record.JobRecords;
import org.jmclbench.core.timeline.Timeline;

/**
 * Under terminate, before the measured window: three releases, 2 ms apart, of jobs that only
 * poll their abort signal until it answers yes (or 4 ms pass), so that the first two are aborted
 * by the next release. An engine runs it through its own release path, so that the JIT's profile
 * of that path holds the answer "abort" before the job's loops are compiled with it inlined:
 * HotSpot 17 compiled a never-seen answer as an uncommon trap, and each task's first abort
 * deoptimised before its poll could note it (80 to 150 us of noticing, measured in the javase
 * engine). The job code stays as cold as the runtime leaves it: the rehearsal's job is not the MCL.
 */
public final class AbortRehearsal {
    static final long SPACING_NS = 2_000_000L;

    private AbortRehearsal() {
    }

    /** The releases: predict, update, predict, {@link #SPACING_NS} apart, with no deadline. */
    public static ReleaseSchedule schedule() {
        long[] release = {0, SPACING_NS, 2 * SPACING_NS};
        long[] deadline = {Long.MAX_VALUE, Long.MAX_VALUE, Long.MAX_VALUE};
        int[] task = {Timeline.PREDICT, Timeline.UPDATE, Timeline.PREDICT};
        return ReleaseSchedule.of(release, deadline, task);
    }

    /**
     * Records for the rehearsal's own three releases: the dataset's timeline can hold fewer events
     * (a laser and an odometry line make a dataset of two), which the run must not fail on.
     */
    public static JobRecords records() {
        double s = SPACING_NS / 1e9;
        return new JobRecords(Timeline.merge(new double[] {0, 2 * s}, new double[] {s}), false);
    }

    /** A job that polls until aborted, for at most two spacings; it commits nothing. */
    public static EventJob job() {
        return (k, abort) -> {
            long until = System.nanoTime() + 2 * SPACING_NS;
            while (System.nanoTime() < until) {
                if (abort.abortRequested()) {
                    return false;
                }
            }
            return true;
        };
    }
}
