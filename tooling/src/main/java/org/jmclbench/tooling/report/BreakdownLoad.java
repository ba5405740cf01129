package org.jmclbench.tooling.report;

import java.util.Comparator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * A configuration's breakdown load read from its queue runs in the store (the runs the
 * {@code capacity} command's search or a matrix made): the largest particle count at which every
 * job of both tasks completed by its deadline in every repetition, every smaller count of the
 * store holding too, and the smallest count above it at which one did not. Under queue no job is
 * dropped or aborted, so a run's missCount is its late jobs: a count holds when every repetition
 * ran and none was late.
 *
 * @param holds the largest count that held, or null when the smallest count in the store failed
 * @param fails the smallest count above it that failed, or null when every count held
 */
record BreakdownLoad(Integer holds, Integer fails) {

    /** Per configuration of the queue cells, in the order of {@code configs}. */
    static Map<String, BreakdownLoad> of(List<ReportModel.Cell> queueCells, List<String> configs) {
        Map<String, BreakdownLoad> out = new LinkedHashMap<>();
        for (String config : configs) {
            List<ReportModel.Cell> cs = queueCells.stream().filter(c -> c.config.equals(config) && c.policy.equals("queue"))
                    .sorted(Comparator.comparingInt(c -> c.particles)).toList();
            if (cs.isEmpty()) {
                continue;
            }
            Integer holds = null;
            Integer fails = null;
            for (ReportModel.Cell c : cs) {
                if (c.unsupported > 0 && c.ok == 0) {
                    continue;
                }
                if (!held(c)) {
                    fails = c.particles;
                    break;
                }
                holds = c.particles;
            }
            out.put(config, new BreakdownLoad(holds, fails));
        }
        return out;
    }

    /** Every repetition ran to its end and no job of any was late. */
    static boolean held(ReportModel.Cell c) {
        ReportModel.Agg misses = c.metrics.get(Metric.MISS_COUNT.name());
        return c.ok > 0 && c.failed == 0 && c.timeout == 0 && misses != null && misses.max() != null && misses.max() == 0;
    }
}
