package org.jmclbench.tooling.attribution;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;

/**
 * Separates the first seconds of a run (class loading, interpretation, JIT compilation) from
 * the rest, so that start-up effects show instead of hiding in the run's averages.
 *
 * <p>A job belongs to the warm part when it was released before the boundary (default 2 s
 * after the run start), else to the steady part. For each task ({@code predict},
 * {@code update}, {@code all}) and part it gives the task latency and response time statistics
 * (count, mean, stdev, min, p50, p90, p99, p999, max; the definitions of summary.json), the
 * jobs released and the jobs missed or late, as {@link MetricRow}s:
 * {@code taskLatencyNs.warm}, {@code taskLatencyNs.steady}, {@code responseTimeNs.warm},
 * {@code responseTimeNs.steady} (stats), {@code released.warm}, {@code released.steady},
 * {@code missedOrLate.warm}, {@code missedOrLate.steady} (stat {@code value}), and the
 * boundary itself as task {@code run}, metric {@code warmupBoundaryNs}.
 */
public final class WarmupSplit {
    /** The default boundary: the first 2 s of the run are its warm-up. */
    public static final long DEFAULT_BOUNDARY_NS = 2_000_000_000L;

    private WarmupSplit() {
    }

    /** The metric rows of the split of {@code jobs} (both tasks of one run) at {@code boundaryNs}. */
    public static List<MetricRow> metrics(List<JobRecord> jobs, long boundaryNs) {
        List<MetricRow> rows = new ArrayList<>();
        rows.add(new MetricRow("run", "warmupBoundaryNs", "value", boundaryNs));
        for (String task : List.of("predict", "update", "all")) {
            for (boolean warm : new boolean[] {true, false}) {
                String part = warm ? "warm" : "steady";
                List<JobRecord> in = jobs.stream()
                        .filter(j -> task.equals("all") || j.task().equals(task))
                        .filter(j -> (j.releaseNs() < boundaryNs) == warm).toList();
                long[] latency = in.stream().filter(j -> j.completed() && j.startNs() >= 0 && j.endNs() >= 0)
                        .mapToLong(j -> j.endNs() - j.startNs()).toArray();
                long[] response = in.stream().filter(j -> j.completed() && j.endNs() >= 0)
                        .mapToLong(j -> j.endNs() - j.releaseNs()).toArray();
                addStats(rows, task, "taskLatencyNs." + part, SampleStats.of(latency));
                addStats(rows, task, "responseTimeNs." + part, SampleStats.of(response));
                rows.add(new MetricRow(task, "released." + part, "value", in.size()));
                rows.add(new MetricRow(task, "missedOrLate." + part, "value", in.stream().filter(JobRecord::missedOrLate).count()));
            }
        }
        return rows;
    }

    /** The stats of an empty sample are left out (no row), as summary.json writes them as null. */
    private static void addStats(List<MetricRow> rows, String task, String metric, SampleStats s) {
        rows.add(new MetricRow(task, metric, "count", s.count()));
        if (s.count() == 0) {
            return;
        }
        for (Map.Entry<String, Double> e : Map.of("mean", s.mean(), "stdev", s.stdev(), "min", (double) s.min(),
                "p50", (double) s.p50(), "p90", (double) s.p90(), "p99", (double) s.p99(), "p999", (double) s.p999(),
                "max", (double) s.max()).entrySet()) {
            rows.add(new MetricRow(task, metric, e.getKey(), e.getValue()));
        }
    }
}
