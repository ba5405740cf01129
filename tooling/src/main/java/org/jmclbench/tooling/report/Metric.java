package org.jmclbench.tooling.report;

import org.jmclbench.tooling.store.StoredRun;

/**
 * A per-run value the report and compare aggregate over repetitions: read from the
 * flattened {@code metrics} table, else from the run's summary.json (docs/FORMATS.md 4-5).
 */
public enum Metric {
    /** The thesis's missCount: dropped, dropped or aborted, or late jobs by the policy ({@link #missCountJobs}). */
    MISS_COUNT("missCount", "jobs", 1, "/missCount", "run/missCount/value", "all/missCount/value", "all/missCount/mean"),
    LATE("late", "jobs", 1, "/tasks/all/late", "all/late/value", "run/late/value"),
    /** Jobs not completed by their deadline (late + skipped + terminated), both tasks: the real-time miss count. */
    DEADLINE_MISSES("deadline misses", "jobs", 1, "/tasks/all/deadlineMisses"),
    /** A task's deadline misses over its released jobs in one run (a ratio in [0, 1]). */
    MISS_RATIO_PREDICT("predict miss ratio", "fraction of jobs", 1, "/tasks/predict/missRatio"),
    MISS_RATIO_UPDATE("update miss ratio", "fraction of jobs", 1, "/tasks/update/missRatio"),
    LATENCY_MEAN("task latency mean", "ms", 1e-6, "/tasks/all/taskLatencyNs/mean", "all/taskLatencyNs/mean"),
    LATENCY_P99("task latency p99", "ms", 1e-6, "/tasks/all/taskLatencyNs/p99", "all/taskLatencyNs/p99"),
    LATENCY_MAX("task latency max", "ms", 1e-6, "/tasks/all/taskLatencyNs/max", "all/taskLatencyNs/max"),
    JITTER_MEAN("release jitter mean", "ms", 1e-6, "/tasks/all/releaseJitterNs/mean", "all/releaseJitterNs/mean"),
    JITTER_P99("release jitter p99", "ms", 1e-6, "/tasks/all/releaseJitterNs/p99", "all/releaseJitterNs/p99"),
    JITTER_MAX("release jitter max", "ms", 1e-6, "/tasks/all/releaseJitterNs/max", "all/releaseJitterNs/max"),
    DEVIATION("deviation xy mean", "m", 1, "/deviation/xy/mean", "run/deviationXY/mean", "run/deviationXY/value",
            "all/deviationXY/mean", "all/deviationXY/value");


    /** Name shown in tables. */
    public final String label;
    /** Unit of {@link #of} (after {@link #scale}). */
    public final String unit;
    private final double scale;
    private final String summaryPointer;
    private final String[] metricKeys;

    Metric(String label, String unit, double scale, String summaryPointer, String... metricKeys) {
        this.label = label;
        this.unit = unit;
        this.scale = scale;
        this.summaryPointer = summaryPointer;
        this.metricKeys = metricKeys;
    }

    /** The value of a run in {@link #unit}, or null when the run has none (failed, or not recorded). */
    public Double of(StoredRun run) {
        return run.ok() ? inUnit(run.value(summaryPointer, metricKeys), scale) : null;
    }

    /**
     * The jobs the thesis's missCount counts under {@code policy} (docs/FORMATS.md 4): the dropped
     * ones under skip, the dropped or aborted ones under terminate, the late ones under queue. A
     * late job under skip is a deadline miss it does not count, so it is never called the misses.
     */
    public static String missCountJobs(String policy) {
        return switch (policy == null ? "" : policy) {
            case "skip" -> "dropped jobs";
            case "terminate" -> "dropped or aborted jobs";
            case "queue" -> "late jobs";
            default -> "missed jobs";
        };
    }

    /** A run's stored value {@code v} times {@code scale}, a metric's unit; NaN (written null) is no value either. */
    static Double inUnit(Double v, double scale) {
        return v == null || v.isNaN() ? null : v * scale;
    }
}
