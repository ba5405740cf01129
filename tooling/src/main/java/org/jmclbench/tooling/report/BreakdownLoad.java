package org.jmclbench.tooling.report;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.Comparator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

import org.jmclbench.tooling.cli.Counts;

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
 * @param failedRuns null when that count failed by a late job; else how its runs failed (crashed, timed out)
 *                   or why the runtime cannot run it (unsupported, above a count that held), which bounds the
 *                   load by the runtime's limits, not by a deadline
 * @param late       when that count failed by late jobs, how: a bracket whose upper count was late in one
 *                   repetition by a job or two rests on those jobs, and a repeated search may move it a step
 */
record BreakdownLoad(Integer holds, Integer fails, String failedRuns, Late late) {

    /** The count failed by late jobs in {@code repetitions} of its {@code of} completed repetitions, at most {@code mostJobs} in one. */
    record Late(int repetitions, int of, int mostJobs) {
        @Override
        public String toString() {
            return repetitions + " of " + of + (of == 1 ? " repetition" : " repetitions") + " late, by "
                    + (repetitions == 1 ? "" : "at most ") + mostJobs + (mostJobs == 1 ? " job" : " jobs");
        }

        /** One repetition late by a job or two: the bracket rests on those few jobs. */
        boolean marginal() {
            return repetitions == 1 && mostJobs <= 2;
        }
    }

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
            String failedRuns = null;
            Late late = null;
            for (ReportModel.Cell c : cs) {
                if (c.unsupported > 0 && c.ok == 0 && holds == null) {
                    continue; // nothing of this configuration has run yet (an engine's memory style it lacks)
                }
                if (!held(c)) {
                    fails = c.particles;
                    failedRuns = failedRuns(c);
                    late = failedRuns == null ? late(c) : null;
                    break;
                }
                holds = c.particles;
            }
            out.put(config, new BreakdownLoad(holds, fails, failedRuns, late));
        }
        return out;
    }

    /**
     * The counts above {@code fails} at which some completed repetitions of {@code config} still had
     * every job by its deadline ({@code 102400 held in 2 of 3 repetitions}), lowest first: its
     * misses near the bracket are chance, and a repeated search may bracket it elsewhere, even more
     * than a step away. Empty when nothing above held, or nothing failed.
     */
    static List<String> heldAbove(List<ReportModel.Cell> queueCells, String config, Integer fails) {
        List<String> out = new ArrayList<>();
        if (fails == null) {
            return out;
        }
        queueCells.stream().filter(c -> c.config.equals(config) && c.policy.equals("queue") && c.particles > fails)
                .sorted(Comparator.comparingInt(c -> c.particles)).forEach(c -> {
                    ReportModel.Agg misses = c.metrics.get(Metric.MISS_COUNT.name());
                    long held = misses == null || misses.values() == null ? 0 : Arrays.stream(misses.values()).filter(v -> v == 0).count();
                    if (held > 0) {
                        out.add(c.particles + " held in " + held + " of " + Counts.of(misses.n(), "repetition"));
                    }
                });
        return out;
    }

    /**
     * How a count's runs failed, when some did and none completed without a late job: {@code 3 of 3
     * runs failed: the HVM executable failed (exit status 139)}, or {@code the runtime cannot run it:
     * the HVM holds at most 65,535 particles (...)} when every run was unsupported; null when a
     * completed run had a late job.
     */
    static String failedRuns(ReportModel.Cell c) {
        if (c.unsupported > 0 && c.ok + c.failed + c.timeout == 0) {
            // "--particles 66399: the HVM holds at most 65,535 particles (...)" -> what follows the option
            String why = firstFailure(c).replaceFirst("^--particles \\d+: ", "");
            return "the runtime cannot run it" + (why.isBlank() ? "" : ": " + why);
        }
        int bad = c.failed + c.timeout;
        Double late = mostLate(c);
        if (bad == 0 || (late != null && late > 0)) {
            return null;
        }
        String first = firstFailure(c);
        // "exit code 1: jmclbench: failure: the HVM executable failed (exit status 139): warning: ..." -> its first clause
        first = first.replaceFirst("^exit code -?\\d+: ", "").replaceFirst("^jmclbench: (failure: )?", "");
        int cut = first.indexOf(": ");
        first = cut > 0 ? first.substring(0, cut) : first;
        return bad + " of " + Counts.of(c.ok + bad, "run") + " failed" + (first.isBlank() ? "" : ": " + first);
    }

    /** How a count's completed repetitions were late; null when none completed. */
    static Late late(ReportModel.Cell c) {
        ReportModel.Agg misses = c.metrics.get(Metric.MISS_COUNT.name());
        if (misses == null || misses.n() == 0) {
            return null;
        }
        int lateRepetitions = 0;
        for (double v : misses.values()) {
            lateRepetitions += v > 0 ? 1 : 0;
        }
        return new Late(lateRepetitions, misses.n(), (int) Math.round(misses.max()));
    }

    private static String firstFailure(ReportModel.Cell c) {
        return c.failures.stream().map(ReportModel.Failure::failure).filter(f -> f != null && !f.isBlank())
                .findFirst().orElse("");
    }

    /** Every repetition ran to its end and no job of any was late. */
    static boolean held(ReportModel.Cell c) {
        Double late = mostLate(c);
        return c.ok > 0 && c.failed == 0 && c.timeout == 0 && late != null && late == 0;
    }

    /** The most late jobs of a completed repetition (under queue, its missCount); null when none completed. */
    private static Double mostLate(ReportModel.Cell c) {
        ReportModel.Agg misses = c.metrics.get(Metric.MISS_COUNT.name());
        return misses == null ? null : misses.max();
    }
}
