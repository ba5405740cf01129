package org.jmclbench.workload.release;

import java.util.Arrays;
import org.jmclbench.core.timeline.Timeline;

/**
 * The release time, absolute deadline and task of every merged event, in nanoseconds from
 * the run start, computed once before the run (FORMATS.md section 3): predict is due 50 ms
 * after its release, update at the release of the next laser event (the last one 250 ms after
 * its release), everything times the time scale.
 */
public final class ReleaseSchedule {
    /**
     * Relative deadline of a predict job, seconds: the thesis's odometry period, fixed whatever the
     * dataset's (the scj mission's periodic handler uses the dataset's mean interval instead).
     */
    public static final double PREDICT_DEADLINE_S = 0.050;
    /** Relative deadline of the last update job (one laser revolution's longest gap), seconds. */
    public static final double LAST_UPDATE_DEADLINE_S = 0.250;

    final long[] releaseNs;
    final long[] deadlineNs;
    final int[] task;

    ReleaseSchedule(long[] releaseNs, long[] deadlineNs, int[] task) {
        this.releaseNs = releaseNs;
        this.deadlineNs = deadlineNs;
        this.task = task;
    }

    /** A schedule from explicit arrays (ns from the run start), e.g. a synthetic periodic one. */
    public static ReleaseSchedule of(long[] releaseNs, long[] deadlineNs, int[] task) {
        if (releaseNs.length != deadlineNs.length || releaseNs.length != task.length) {
            throw new IllegalArgumentException("schedule arrays differ in length");
        }
        for (int k = 1; k < releaseNs.length; k++) {
            if (releaseNs[k] < releaseNs[k - 1]) {
                throw new IllegalArgumentException("release times decrease at event " + k);
            }
        }
        return new ReleaseSchedule(releaseNs.clone(), deadlineNs.clone(), task.clone());
    }

    /** The schedule of a whole timeline replayed at {@code timeScale} (1 = real time). */
    public static ReleaseSchedule of(Timeline timeline, double timeScale) {
        int n = timeline.size();
        long[] release = new long[n];
        long[] deadline = new long[n];
        int[] task = new int[n];
        for (int k = 0; k < n; k++) {
            release[k] = toNs(timeline.time(k), timeScale);
            task[k] = timeline.task(k);
        }
        long nextLaser = -1;
        for (int k = n - 1; k >= 0; k--) {
            if (task[k] == Timeline.PREDICT) {
                deadline[k] = release[k] + toNs(PREDICT_DEADLINE_S, timeScale);
            } else {
                deadline[k] = nextLaser >= 0 ? nextLaser
                        : release[k] + toNs(LAST_UPDATE_DEADLINE_S, timeScale);
                nextLaser = release[k];
            }
        }
        return new ReleaseSchedule(release, deadline, task);
    }

    static long toNs(double seconds, double timeScale) {
        return Math.round(seconds * timeScale * 1e9);
    }

    /** Number of events. */
    public int size() {
        return releaseNs.length;
    }

    /** The number of leading events released strictly before {@code seconds} of timeline. */
    public int countBefore(double seconds, double timeScale) {
        long limit = toNs(seconds, timeScale);
        int n = 0;
        while (n < releaseNs.length && releaseNs[n] < limit) {
            n++;
        }
        return n;
    }

    /** The first {@code n} events, with the deadlines they have in the whole timeline. */
    public ReleaseSchedule prefix(int n) {
        return new ReleaseSchedule(Arrays.copyOf(releaseNs, n), Arrays.copyOf(deadlineNs, n),
                Arrays.copyOf(task, n));
    }

    /** How many events of task {@code t}. */
    int countOf(int t) {
        int c = 0;
        for (int x : task) {
            if (x == t) {
                c++;
            }
        }
        return c;
    }

    /** Scheduled release of event k, ns from the run start. */
    public long releaseNs(int k) {
        return releaseNs[k];
    }

    /** Absolute deadline of event k, ns from the run start. */
    public long deadlineNs(int k) {
        return deadlineNs[k];
    }

    /** Task of event k (Timeline.PREDICT or Timeline.UPDATE). */
    public int task(int k) {
        return task[k];
    }
}
