package org.jmclbench.tooling.report;

import java.util.List;

import org.jmclbench.tooling.store.StoredRun;

/**
 * A per-run value of one task ({@code predict}, {@code update} or {@code all}), the deadline
 * accounting of docs/FORMATS.md 4: read from the flattened {@code metrics} table
 * ({@code <task>/<field>/<stat>}), else from summary.json ({@code tasks.<task>.<field>}). A cell
 * keeps the mean over its repetitions under {@link #key} in {@link ReportModel.Cell#metrics}.
 *
 * <p>Response times are over every released job: a dropped or aborted job counts as +infinity
 * (the summary's {@code "inf"}), so a quantile that falls among them is
 * {@link Double#POSITIVE_INFINITY}, never left out.
 */
public enum TaskMetric {
    MISS_RATIO("miss ratio", "fraction of released jobs", 1, "missRatio", "value"),
    DEADLINE_MISSES("deadline misses", "jobs", 1, "deadlineMisses", "value"),
    LATE("late", "jobs", 1, "late", "value"),
    DROPPED("dropped (skipped)", "jobs", 1, "skipped", "value"),
    ABORTED("aborted (terminated)", "jobs", 1, "terminated", "value"),
    RESPONSE_P50("response time p50", "ms", 1e-6, "responseTimeReleasedNs", "p50"),
    RESPONSE_P99("response time p99", "ms", 1e-6, "responseTimeReleasedNs", "p99"),
    RESPONSE_MAX("response time max", "ms", 1e-6, "responseTimeReleasedNs", "max"),
    LATENCY_P99("task latency p99", "ms", 1e-6, "taskLatencyNs", "p99"),
    /** The slowest job: with the particle count, the cost of a particle step that bounds an abort. */
    LATENCY_MAX("task latency max", "ms", 1e-6, "taskLatencyNs", "max"),
    JITTER_P99("release jitter p99", "ms", 1e-6, "releaseJitterNs", "p99"),
    /** From the abort request to the aborted job's end, over the jobs an abort took hold of (terminate). */
    ABORT_P50("abort latency p50", "ms", 1e-6, "abortLatencyNs", "p50"),
    ABORT_P99("abort latency p99", "ms", 1e-6, "abortLatencyNs", "p99"),
    ABORT_MAX("abort latency max", "ms", 1e-6, "abortLatencyNs", "max"),
    /**
     * The abort latency's first part: from the request to the poll (or delivery point) that saw
     * it, what the static bound bounds; over the aborts whose engine recorded it.
     */
    ABORT_NOTICE_P50("abort noticed p50", "ms", 1e-6, "abortNoticeNs", "p50"),
    ABORT_NOTICE_P99("abort noticed p99", "ms", 1e-6, "abortNoticeNs", "p99"),
    ABORT_NOTICE_MAX("abort noticed max", "ms", 1e-6, "abortNoticeNs", "max"),
    /** Its second part: from that poll to the job's end (returning, or the AIE thrown and unwound). */
    ABORT_STOP_MAX("abort stopping max", "ms", 1e-6, "abortStopNs", "max");

    /** The tasks a cell aggregates every task metric for. */
    public static final List<String> TASKS = List.of("predict", "update", "all");

    /** Name shown in titles and tables. */
    public final String label;
    /** Unit of {@link #of} (after its scale). */
    public final String unit;
    private final double scale;
    private final String field;
    private final String stat;

    TaskMetric(String label, String unit, double scale, String field, String stat) {
        this.label = label;
        this.unit = unit;
        this.scale = scale;
        this.field = field;
        this.stat = stat;
    }

    /** The key of the cell's aggregate for {@code task}: {@code predict.MISS_RATIO}. */
    public String key(String task) {
        return task + "." + name();
    }

    /** A ratio lies in [0, 1]; its interval is clipped there. */
    boolean ratio() {
        return this == MISS_RATIO;
    }

    /**
     * The value of a run for {@code task} in {@link #unit}, or null when the run has none (failed,
     * or a summary that predates the field). A run written before {@code deadlineMisses} and
     * {@code missRatio} gets them from their definition, {@code late + skipped + terminated} (over
     * {@code released}).
     */
    public Double of(StoredRun run, String task) {
        if (!run.ok()) {
            return null;
        }
        Double v = raw(run, task, field, stat);
        if (v == null && (this == DEADLINE_MISSES || this == MISS_RATIO)) {
            Double late = raw(run, task, "late", "value");
            Double skipped = raw(run, task, "skipped", "value");
            Double terminated = raw(run, task, "terminated", "value");
            Double released = released(run, task);
            if (late != null && skipped != null && terminated != null) {
                double misses = late + skipped + terminated;
                v = this == DEADLINE_MISSES ? (Double) misses : released != null && released > 0 ? misses / released : null;
            }
        }
        return Metric.inUnit(v, scale);
    }

    /** The jobs of {@code task} the run released (null: not told). */
    static Double released(StoredRun run, String task) {
        return raw(run, task, "released", "value");
    }

    /** A number of the metrics table ({@code task/field/stat}) or the summary ({@code tasks.task.field[.stat]}). */
    private static Double raw(StoredRun run, String task, String field, String stat) {
        String pointer = "/tasks/" + task + "/" + field + ("value".equals(stat) ? "" : "/" + stat);
        return run.value(pointer, task + "/" + field + "/" + stat);
    }
}
