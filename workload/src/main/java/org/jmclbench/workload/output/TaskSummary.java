package org.jmclbench.workload.output;

import java.util.Arrays;

import org.jmclbench.core.policy.OverrunPolicy;
import org.jmclbench.core.record.JobRecords;
import org.jmclbench.workload.RunOptions;
import org.jmclbench.workload.record.Stats;

/**
 * The counts and statistics of one task (or of all, task = -1) for summary.json
 * (docs/FORMATS.md section 4): the thesis's missCount, the deadline accounting of every
 * release (done by its deadline, late, skipped = dropped, terminated = aborted, and the miss
 * ratio) and the response time over every release, where a job that never completed counts as
 * +infinity so that dropping work cannot make a runtime look faster.
 */
public final class TaskSummary {
    /** The quantiles of {@code responseTimeReleasedNs}, per mille, in the order written. */
    static final int[] RELEASED_QUANTILES = {0, 500, 900, 990, 999, 1000};
    static final String[] RELEASED_QUANTILE_NAMES = {"min", "p50", "p90", "p99", "p999", "max"};

    int released;
    int completed;
    int done;
    int late;
    int skipped;
    int terminated;
    int missCount;
    Stats releaseJitter;
    Stats taskLatency;
    Stats responseTime;
    Stats cpu;
    /** Abort latency (end - abort_ns) of the jobs an abort took hold of; of those, how many completed anyway. */
    Stats abortLatency;
    /** The abort latency's two parts, over the aborts whose job recorded when it saw the request: request to seen, seen to end. */
    Stats abortNotice;
    Stats abortStop;
    int abortsCompleted;
    /** Response time at {@link #RELEASED_QUANTILES} over every release; {@link Stats#NOT_COMPLETED} = +infinity. */
    final long[] releasedResponse = new long[RELEASED_QUANTILES.length];

    private TaskSummary() {
    }

    static TaskSummary of(JobRecords r, int task, RunOptions o) {
        TaskSummary s = count(r, task);
        if (o.ideal) {
            s.missCount = 0;
        } else if (o.policy == OverrunPolicy.QUEUE) {
            s.missCount = s.late;
        } else {
            s.missCount = s.skipped + s.terminated;
        }
        return s;
    }

    /** Everything but the policy-dependent missCount, of the jobs of {@code task} (-1: both tasks). */
    public static TaskSummary count(JobRecords r, int task) {
        TaskSummary s = new TaskSummary();
        int n = r.size();
        long[] jitter = new long[n];
        long[] latency = new long[n];
        long[] response = new long[n];
        long[] cpu = new long[n];
        long[] abort = new long[n];
        long[] notice = new long[n];
        long[] stop = new long[n];
        int na = 0;
        int ns = 0;
        int nj = 0;
        int nl = 0;
        int nr = 0;
        int nc = 0;
        for (int k = 0; k < n; k++) {
            if (task >= 0 && r.timeline.task(k) != task) {
                continue;
            }
            byte out = r.outcome[k];
            if (out == JobRecords.PENDING) {
                continue; // never released (a run cut short)
            }
            s.released++;
            switch (out) {
                case JobRecords.DONE:
                    s.done++;
                    break;
                case JobRecords.LATE:
                    s.late++;
                    break;
                case JobRecords.SKIPPED:
                    s.skipped++;
                    break;
                case JobRecords.TERMINATED:
                    s.terminated++;
                    break;
                default:
                    break;
            }
            if (r.startNs[k] >= 0 && r.releaseNs[k] >= 0) {
                jitter[nj++] = r.startNs[k] - r.releaseNs[k];
            }
            if (r.completed(k) && r.startNs[k] >= 0 && r.endNs[k] >= 0) {
                latency[nl++] = r.endNs[k] - r.startNs[k];
                if (r.releaseNs[k] >= 0) {
                    response[nr++] = r.endNs[k] - r.releaseNs[k];
                }
            }
            if (r.cpuNs[k] >= 0) {
                cpu[nc++] = r.cpuNs[k];
            }
            long from = r.abortFromNs(k);
            if (from >= 0) {
                abort[na++] = r.endNs[k] - from;
                long seen = r.abortSeenFromNs(k);
                if (seen >= 0) {
                    notice[ns] = seen - from;
                    stop[ns++] = r.endNs[k] - seen;
                }
                if (r.completed(k)) {
                    s.abortsCompleted++;
                }
            }
        }
        s.completed = s.done + s.late;
        s.releaseJitter = Stats.of(jitter, nj);
        s.taskLatency = Stats.of(latency, nl);
        s.responseTime = Stats.of(response, nr);
        s.cpu = Stats.of(cpu, nc);
        s.abortLatency = Stats.of(abort, na);
        s.abortNotice = Stats.of(notice, ns);
        s.abortStop = Stats.of(stop, ns);
        Arrays.sort(response, 0, nr);
        for (int q = 0; q < RELEASED_QUANTILES.length && s.released > 0; q++) {
            s.releasedResponse[q] = Stats.rankOfReleases(response, nr, s.released, RELEASED_QUANTILES[q]);
        }
        return s;
    }

    public int released() {
        return released;
    }

    public int done() {
        return done;
    }

    public int late() {
        return late;
    }

    public int skipped() {
        return skipped;
    }

    public int terminated() {
        return terminated;
    }

    /** Abort latency, ns from when an abort took hold of a job to its end, over the jobs it took hold of. */
    public Stats abortLatency() {
        return abortLatency;
    }

    /** Noticing: ns from the abort request to the poll that saw it, over the aborts whose job recorded it. */
    public Stats abortNotice() {
        return abortNotice;
    }

    /** Stopping: ns from the poll that saw the abort request to the job's end, over the same aborts. */
    public Stats abortStop() {
        return abortStop;
    }

    /** Jobs an abort took hold of that completed all the same (the request came too late, or was deferred). */
    public int abortsCompleted() {
        return abortsCompleted;
    }

    /** Releases whose job did not complete by its deadline: late + skipped + terminated, under every policy. */
    public int deadlineMisses() {
        return late + skipped + terminated;
    }

    /** deadlineMisses / released; NaN (written null) when nothing was released. */
    public double missRatio() {
        return released == 0 ? Double.NaN : (double) deadlineMisses() / released;
    }

    /** The response time at {@code RELEASED_QUANTILES[q]} over every release ({@link Stats#NOT_COMPLETED}: +infinity). */
    public long releasedResponse(int q) {
        return releasedResponse[q];
    }

    void writeTo(Json j) {
        j.beginObject();
        j.name("released").value(released);
        j.name("completed").value(completed);
        j.name("done").value(done);
        j.name("late").value(late);
        j.name("skipped").value(skipped);
        j.name("terminated").value(terminated);
        j.name("missCount").value(missCount);
        RunWriter.writeStats(j, "releaseJitterNs", releaseJitter);
        RunWriter.writeStats(j, "taskLatencyNs", taskLatency);
        RunWriter.writeStats(j, "responseTimeNs", responseTime);
        RunWriter.writeStats(j, "cpuNs", cpu);
        RunWriter.writeStats(j, "abortLatencyNs", abortLatency);
        RunWriter.writeStats(j, "abortNoticeNs", abortNotice);
        RunWriter.writeStats(j, "abortStopNs", abortStop);
        j.name("abortsCompleted").value(abortsCompleted);
        j.name("deadlineMisses").value(deadlineMisses());
        j.name("missRatio").value(missRatio());
        j.name("responseTimeReleasedNs").beginObject();
        j.name("count").value(released);
        j.name("completed").value(responseTime.count);
        for (int q = 0; q < RELEASED_QUANTILES.length; q++) {
            j.name(RELEASED_QUANTILE_NAMES[q]);
            if (released == 0) {
                j.nullValue();
            } else if (releasedResponse[q] == Stats.NOT_COMPLETED) {
                j.value("inf");
            } else {
                j.value(releasedResponse[q]);
            }
        }
        j.endObject();
        j.endObject();
    }
}
