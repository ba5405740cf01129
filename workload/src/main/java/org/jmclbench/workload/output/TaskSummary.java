package org.jmclbench.workload.output;

import org.jmclbench.core.record.JobRecords;
import org.jmclbench.workload.RunOptions;
import org.jmclbench.workload.record.Samples;
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
        s.missCount = o.ideal ? 0 : o.policy.missCount(s.late, s.skipped, s.terminated);
        return s;
    }

    /** Everything but the policy-dependent missCount, of the jobs of {@code task} (-1: both tasks). */
    public static TaskSummary count(JobRecords r, int task) {
        TaskSummary s = new TaskSummary();
        int n = r.size();
        Samples jitter = new Samples(n);
        Samples latency = new Samples(n);
        Samples response = new Samples(n);
        Samples cpu = new Samples(n);
        Samples abort = new Samples(n);
        Samples notice = new Samples(n);
        Samples stop = new Samples(n);
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
                jitter.add(r.startNs[k] - r.releaseNs[k]);
            }
            if (r.completed(k) && r.startNs[k] >= 0 && r.endNs[k] >= 0) {
                latency.add(r.endNs[k] - r.startNs[k]);
                if (r.releaseNs[k] >= 0) {
                    response.add(r.endNs[k] - r.releaseNs[k]);
                }
            }
            if (r.cpuNs[k] >= 0) {
                cpu.add(r.cpuNs[k]);
            }
            long from = r.abortFromNs(k);
            if (from >= 0) {
                abort.add(r.endNs[k] - from);
                long seen = r.abortSeenFromNs(k);
                if (seen >= 0) {
                    notice.add(seen - from);
                    stop.add(r.endNs[k] - seen);
                }
                if (r.completed(k)) {
                    s.abortsCompleted++;
                }
            }
        }
        s.completed = s.done + s.late;
        s.releaseJitter = jitter.stats();
        s.taskLatency = latency.stats();
        s.responseTime = response.stats();
        s.cpu = cpu.stats();
        s.abortLatency = abort.stats();
        s.abortNotice = notice.stats();
        s.abortStop = stop.stats();
        long[] sortedResponse = response.sorted();
        for (int q = 0; q < RELEASED_QUANTILES.length && s.released > 0; q++) {
            s.releasedResponse[q] = Stats.rankOfReleases(sortedResponse, sortedResponse.length, s.released,
                    RELEASED_QUANTILES[q]);
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
