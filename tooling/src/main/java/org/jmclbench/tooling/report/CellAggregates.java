package org.jmclbench.tooling.report;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;

import org.jmclbench.tooling.report.ReportModel.Cell;
import org.jmclbench.tooling.report.ReportModel.MemoryArea;
import org.jmclbench.tooling.store.MemoryAreaRow;
import org.jmclbench.tooling.store.StoredRun;

import com.fasterxml.jackson.databind.JsonNode;

/**
 * What a cell of the report sums or compares over its completed runs: the memory areas, the
 * deadline accounting pooled over repetitions, the causes of misses, and which cells the
 * separation rule cannot tell apart from the one with the fewest misses.
 */
final class CellAggregates {

    private CellAggregates() {
    }

    /** Each area's largest size and peak over the runs, and its mean bytes per release, in {@link ReportModel#AREA_ORDER}. */
    static List<MemoryArea> memoryAreas(List<StoredRun> ok) {
        Map<String, List<MemoryAreaRow>> byName = new LinkedHashMap<>();
        for (StoredRun r : ok) {
            for (MemoryAreaRow a : r.areas) {
                byName.computeIfAbsent(a.name(), k -> new ArrayList<>()).add(a);
            }
        }
        List<MemoryArea> out = new ArrayList<>();
        for (Map.Entry<String, List<MemoryAreaRow>> e : byName.entrySet()) {
            List<MemoryAreaRow> as = e.getValue();
            Long size = as.stream().map(MemoryAreaRow::size).filter(v -> v != null).max(Long::compare).orElse(null);
            Long peak = as.stream().map(MemoryAreaRow::peakBytes).filter(v -> v != null).max(Long::compare).orElse(null);
            List<Double> perRelease = as.stream().map(MemoryAreaRow::bytesPerRelease).filter(v -> v != null).toList();
            Double mean = perRelease.isEmpty() ? null
                    : SeriesTable.round(perRelease.stream().mapToDouble(Double::doubleValue).average().orElse(0));
            out.add(new MemoryArea(e.getKey(), size, peak, mean, as.size(),
                    summedAreaField(ok, e.getKey(), "releases"), summedAreaField(ok, e.getKey(), "allocatingReleases")));
        }
        out.sort(Comparator.comparingInt((MemoryArea a) -> ReportModel.areaRank(a.name())));
        return out;
    }

    /** Fills each cell's {@link Cell#missSeparation} against the other cells of its setting. */
    static void separateMisses(List<Cell> cells) {
        Map<String, List<Cell>> bySetting = new LinkedHashMap<>();
        cells.forEach(c -> bySetting.computeIfAbsent(c.dataset + "\u0000" + c.policy + "\u0000" + c.particles, k -> new ArrayList<>()).add(c));
        for (List<Cell> setting : bySetting.values()) {
            for (int i = 0; i < setting.size(); i++) {
                for (int j = i + 1; j < setting.size(); j++) {
                    Cell a = setting.get(i);
                    Cell b = setting.get(j);
                    Separation.Verdict v = Separation.of(EvaluationData.values(a, Metric.MISS_COUNT),
                            EvaluationData.values(b, Metric.MISS_COUNT)).verdict();
                    a.missSeparation.put(b.config, v.name());
                    b.missSeparation.put(a.config, switch (v) {
                        case A_LOWER -> Separation.Verdict.B_LOWER.name();
                        case B_LOWER -> Separation.Verdict.A_LOWER.name();
                        default -> v.name();
                    });
                }
            }
        }
    }

    /**
     * Per task, released jobs and deadline misses (summary.json tasks.T.released and deadlineMisses,
     * else late + skipped + terminated) summed over the runs: the counts behind a pooled miss ratio.
     */
    static Map<String, long[]> deadlines(List<StoredRun> ok) {
        Map<String, long[]> out = new LinkedHashMap<>();
        for (StoredRun r : ok) {
            JsonNode tasks = r.summary().path("tasks");
            for (String task : List.of("predict", "update", "all")) {
                JsonNode t = tasks.path(task);
                if (!t.path("released").isNumber()) {
                    continue;
                }
                long misses = t.has("deadlineMisses") ? t.path("deadlineMisses").asLong()
                        : t.path("late").asLong() + t.path("skipped").asLong() + t.path("terminated").asLong();
                long[] sum = out.computeIfAbsent(task, k -> new long[2]);
                sum[0] += t.path("released").asLong();
                sum[1] += misses;
            }
        }
        return out;
    }

    /** An area's summary.json field summed over the runs that have it (not in the store's columns); null when none has. */
    static Long summedAreaField(List<StoredRun> ok, String area, String field) {
        Long sum = null;
        for (StoredRun r : ok) {
            for (JsonNode a : r.summary().path("memory").path("areas")) {
                if (area.equals(a.path("name").asText()) && a.path(field).isNumber()) {
                    sum = (sum == null ? 0 : sum) + a.path(field).asLong();
                }
            }
        }
        return sum;
    }

    /**
     * Whether a run carries the attribution's rows: the matrix stores a run whose runtime left no
     * evidence it could read (or more than it keeps) as ok without them.
     */
    static boolean attributed(StoredRun r) {
        return r.metrics.keySet().stream().anyMatch(k -> k.equals("run/cause.jobs/count")
                || k.startsWith("run/cause.") && k.endsWith("/primary"));
    }

    /**
     * Mean over the attributed repetitions of each cause's primary count. A run without
     * attribution rows counts as no evidence, not as zero causes, so it is left out.
     */
    static Map<String, Double> causes(List<StoredRun> ok) {
        Map<String, Double> sum = new TreeMap<>();
        int attributed = 0;
        for (StoredRun r : ok) {
            if (!attributed(r)) {
                continue;
            }
            attributed++;
            for (Map.Entry<String, Double> e : r.metrics.entrySet()) {
                String k = e.getKey();
                if (k.startsWith("run/cause.") && k.endsWith("/primary")) {
                    sum.merge(k.substring("run/cause.".length(), k.length() - "/primary".length()), e.getValue(), Double::sum);
                }
            }
        }
        Map<String, Double> out = new LinkedHashMap<>();
        for (Map.Entry<String, Double> e : sum.entrySet()) {
            out.put(e.getKey(), SeriesTable.round(e.getValue() / attributed));
        }
        return out;
    }
}
