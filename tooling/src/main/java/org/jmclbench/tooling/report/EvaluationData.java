package org.jmclbench.tooling.report;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Objects;
import java.util.TreeSet;
import java.util.function.Predicate;
import java.util.stream.Collectors;

import org.jmclbench.tooling.runtime.RuntimeKind;

import com.fasterxml.jackson.databind.JsonNode;

/**
 * The evaluation's numbers, apart from its text: which cells a question is asked of (the
 * particle sweep, the reference load), their order, and the aggregates and ratios the text
 * quotes, all read from the report's model of the store.
 */
final class EvaluationData {
    final ReportModel model;
    /** The dataset the document is about: the one with the most runs. */
    final String dataset;

    EvaluationData(ReportModel model) {
        this.model = model;
        Map<String, Integer> runsPerDataset = new LinkedHashMap<>();
        model.cells.forEach(c -> runsPerDataset.merge(c.dataset, c.runs, Integer::sum));
        this.dataset = runsPerDataset.entrySet().stream().max(Map.Entry.comparingByValue()).map(Map.Entry::getKey).orElse(null);
    }

    record IntSummary(int min, int max) {
        String text() {
            return min == max ? String.valueOf(min) : min + " to " + max;
        }
    }

    IntSummary repetitions() {
        int min = Integer.MAX_VALUE;
        int max = 0;
        for (ReportModel.Cell c : model.cells) {
            if (c.ok > 0) {
                min = Math.min(min, c.ok);
                max = Math.max(max, c.ok);
            }
        }
        return min == Integer.MAX_VALUE ? new IntSummary(0, 0) : new IntSummary(min, max);
    }

    /** The particle sweep: skip-policy cells of the dataset, per configuration. */
    List<ReportModel.Cell> sweep() {
        return cells(c -> c.policy.equals("skip"));
    }

    List<Integer> sweepCounts() {
        return sweep().stream().map(c -> c.particles).collect(Collectors.toCollection(TreeSet::new)).stream().toList();
    }

    /** Configurations of the sweep that ran the most particle counts (the ones the sweep compares). */
    List<String> sweepConfigs() {
        Map<String, Integer> counts = new LinkedHashMap<>();
        sweep().stream().filter(c -> c.ok > 0).forEach(c -> counts.merge(c.config, 1, Integer::sum));
        int most = counts.values().stream().max(Integer::compare).orElse(0);
        return order(counts.entrySet().stream().filter(e -> e.getValue() == most).map(Map.Entry::getKey).toList());
    }

    /**
     * The load the conclusions compare at: the particle count whose cells completed the most
     * repetitions (the largest such count on a tie); null when nothing completed.
     */
    Integer compareCount() {
        Map<Integer, Integer> most = new java.util.TreeMap<>();
        cells(c -> c.ok > 0).forEach(c -> most.merge(c.particles, c.ok, Math::max));
        int best = most.values().stream().max(Integer::compare).orElse(0);
        Integer out = null;
        for (Map.Entry<Integer, Integer> e : most.entrySet()) {
            if (e.getValue() == best) {
                out = e.getKey();
            }
        }
        return out;
    }

    /** The particle count latency is compared at: the largest of the sweep at which the C baseline's missCount was 0 in every repetition. */
    Integer referenceCount() {
        List<Integer> counts = sweepCounts();
        if (counts.isEmpty()) {
            return null;
        }
        Integer ref = null;
        for (int n : counts) {
            boolean nativeMissed = sweep().stream().filter(c -> c.particles == n && isNative(c))
                    .anyMatch(c -> orZero(max(c, Metric.MISS_COUNT)) > 0);
            if (!nativeMissed) {
                ref = n;
            }
        }
        return ref != null ? ref : counts.get(0);
    }

    /**
     * The largest particle count a configuration sustained with missCount 0 in every completed
     * repetition (under its policy: no dropped, aborted or, under queue, late job), every smaller
     * count of its sweep included; 0 when even its smallest count had a miss.
     */
    static int sustained(List<ReportModel.Cell> cellsOfConfig) {
        int best = 0;
        for (ReportModel.Cell c : cellsOfConfig.stream().filter(x -> x.ok > 0).sorted(Comparator.comparingInt(x -> x.particles)).toList()) {
            ReportModel.Agg a = c.metrics.get(Metric.MISS_COUNT.name());
            if (a == null || a.max() == null || a.max() > 0) {
                break;
            }
            best = c.particles;
        }
        return best;
    }

    record DoctorFinding(String host, String check, String status, String value, String advice) {
    }

    List<DoctorFinding> doctorFindings() {
        List<DoctorFinding> out = new ArrayList<>();
        for (ReportModel.MachineInfo m : model.machines) {
            if (m.checks() == null) {
                continue;
            }
            for (Map<String, String> c : m.checks()) {
                String status = s(c.get("status"));
                if (status.equalsIgnoreCase("WARN") || status.equalsIgnoreCase("FAIL")) {
                    out.add(new DoctorFinding(s(m.hostname()), s(c.get("check")), status, s(c.get("value")), s(c.get("advice"))));
                }
            }
        }
        return out;
    }

    List<ReportModel.Cell> cells(Predicate<ReportModel.Cell> p) {
        return model.cells.stream().filter(c -> c.dataset.equals(dataset)).filter(p).toList();
    }

    static java.util.Optional<ReportModel.Cell> cell(List<ReportModel.Cell> cs, String config, int particles) {
        return cs.stream().filter(c -> c.config.equals(config) && c.particles == particles).findFirst();
    }

    /** Configurations in the report's order (native first, then by name), cells then by particles and policy. */
    List<String> order(List<String> configs) {
        return configs.stream().sorted(Comparator.comparingInt(this::configRank).thenComparing(Comparator.naturalOrder())).toList();
    }

    List<ReportModel.Cell> order(java.util.Collection<ReportModel.Cell> cs) {
        return cs.stream().sorted(Comparator.comparingInt((ReportModel.Cell c) -> configRank(c.config)).thenComparing(c -> c.config)
                .thenComparingInt(c -> c.particles).thenComparing(c -> c.policy)).toList();
    }

    int configRank(String config) {
        ReportModel.ConfigInfo i = model.configs.stream().filter(c -> c.id().equals(config)).findFirst().orElse(null);
        return i != null && i.kind() == RuntimeKind.NATIVE ? 0 : 1;
    }

    ReportModel.ConfigInfo info(ReportModel.Cell c) {
        return model.configs.stream().filter(i -> i.id().equals(c.config)).findFirst().orElseThrow();
    }

    boolean isNative(ReportModel.Cell c) {
        return info(c).kind() == RuntimeKind.NATIVE;
    }

    boolean isHvm(ReportModel.Cell c) {
        return info(c).kind() == RuntimeKind.HVM;
    }

    static boolean sameJvm(ReportModel.ConfigInfo a, ReportModel.ConfigInfo b) {
        return baseRuntime(a.runtime()).equals(baseRuntime(b.runtime())) && Objects.equals(a.profile(), b.profile())
                && Objects.equals(a.machines(), b.machines());
    }

    /** An scj run's runtime is named {@code <jvm>-scj} (docs/RUNNER.md): the JVM is the name without it. */
    static String baseRuntime(String runtime) {
        return runtime.endsWith("-scj") ? runtime.substring(0, runtime.length() - 4) : runtime;
    }

    static Double mean(ReportModel.Cell c, Metric m) {
        ReportModel.Agg a = c.metrics.get(m.name());
        return a == null ? null : a.mean();
    }

    static Double max(ReportModel.Cell c, Metric m) {
        ReportModel.Agg a = c.metrics.get(m.name());
        return a == null ? null : a.max();
    }

    static double orZero(Double d) {
        return d == null ? 0 : d;
    }

    /**
     * {@code mean [low, high]} with {@code decimals} digits: the mean over repetitions and its 95%
     * percentile-bootstrap interval (never below zero; the mean alone with one repetition).
     */
    static String agg(ReportModel.Cell c, Metric m, int decimals) {
        return agg(c, m.name(), decimals);
    }

    /** {@link #agg(ReportModel.Cell, Metric, int)} of the cell's aggregate under {@code key} (a task metric's, a warm-up split's). */
    static String agg(ReportModel.Cell c, String key, int decimals) {
        ReportModel.Agg a = c.metrics.get(key);
        if (a == null || a.mean() == null) {
            return "n/a";
        }
        return a.interval().text(decimals);
    }

    /**
     * {@link Separation}'s rule applied to two cells' per-run values of a metric. The sections test
     * through {@link EvaluationSections#separate}, which keeps each test for section 2.14.
     */
    static Separation.Result separationOf(ReportModel.Cell a, ReportModel.Cell b, Metric m) {
        return Separation.of(values(a, m), values(b, m));
    }

    /**
     * A test of two cells said in a sentence that names it, e.g. "Mann-Whitney U with the bootstrap
     * interval of the ratio (docs/REPORT.md): native lower than temurin-25 (p &lt; 0.001, n = 10 vs
     * 10)." or "...: not separated (p = 0.412, n = 10 vs 10)."
     */
    static String separationSentence(Separation.Result r, ReportModel.Cell a, ReportModel.Cell b) {
        return "Mann-Whitney U with the bootstrap interval of the ratio (docs/REPORT.md): " + r.text(a.config, b.config) + ".";
    }

    /** The per-run values of a metric in a cell (none when the cell has no such metric). */
    static double[] values(ReportModel.Cell c, Metric m) {
        ReportModel.Agg x = c.metrics.get(m.name());
        return x == null || x.values() == null ? new double[0] : x.values();
    }

    /**
     * A task's miss ratio in a cell (jobs not completed by their deadline over jobs released,
     * pooled over the completed repetitions) with its 95% Wilson interval; NaN when nothing was
     * released. {@code task}: predict, update or all.
     */
    static Stats.Interval missRatio(ReportModel.Cell c, String task) {
        long[] d = c.deadlines.get(task);
        return d == null ? Stats.wilson(0, 0) : Stats.wilson(d[1], d[0]);
    }

    /**
     * The jobs missed or late over the jobs released in one window of the runs ({@code WARM}: released
     * in the warm-up, {@code STEADY}: after it), pooled over the completed repetitions, with its 95%
     * Wilson interval; NaN when no run split its jobs. The windows differ in length, so their counts do
     * not compare; their ratios do.
     */
    static Stats.Interval windowMissRatio(ReportModel.Cell c, String window) {
        ReportModel.Agg missed = c.metrics.get(window + "_MISSES");
        ReportModel.Agg released = c.metrics.get(window + "_RELEASED");
        if (missed == null || released == null || missed.values() == null || released.values() == null
                || missed.values().length != released.values().length) {
            return Stats.wilson(0, 0);
        }
        return Stats.wilson(Math.round(java.util.Arrays.stream(missed.values()).sum()),
                Math.round(java.util.Arrays.stream(released.values()).sum()));
    }

    /**
     * A memory area as the evaluation's table gives it: {@code update 248 B (1 of 90 releases
     * allocated, 3 B/release)}; a private memory says how many releases allocated, so that a JIT
     * one-off (rtsj-compat/README.md) does not read as a release style that allocates.
     */
    static String areaText(ReportModel.MemoryArea a) {
        // HVM runs before result-file version 4 (docs/HVM.md) stored their private memories by size only
        StringBuilder t = new StringBuilder(a.name()).append(' ').append(a.peakBytes() == null ? "use not measured" : bytes(a.peakBytes()));
        List<String> notes = new ArrayList<>();
        if (a.releases() != null && a.allocatingReleases() != null) {
            notes.add(a.allocatingReleases() + " of " + a.releases() + " releases allocated");
        }
        if (a.bytesPerRelease() != null) {
            notes.add(bytes(Math.round(a.bytesPerRelease())) + "/release");
        }
        return notes.isEmpty() ? t.toString() : t.append(" (").append(String.join(", ", notes)).append(')').toString();
    }

    static String ratio(Double a, Double b) {
        return a == null || b == null || b == 0 ? "" : num(a / b, 2) + "x";
    }

    static String num(double v, int decimals) {
        return String.format(Locale.ROOT, "%." + decimals + "f", v);
    }

    static String bytes(Long b) {
        if (b == null) {
            return "?";
        }
        return ChartFormats.bytes(b);
    }

    static String first(JsonNode n, String... keys) {
        for (String k : keys) {
            if (n.hasNonNull(k)) {
                return n.get(k).asText();
            }
        }
        return "";
    }

    static String s(String v) {
        return v == null ? "?" : v;
    }
}
