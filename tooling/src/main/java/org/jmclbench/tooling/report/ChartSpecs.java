package org.jmclbench.tooling.report;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Objects;
import java.util.function.Function;

import org.jmclbench.tooling.report.ChartSpec.Axis;
import org.jmclbench.tooling.report.ChartSpec.Band;
import org.jmclbench.tooling.report.ChartSpec.Category;
import org.jmclbench.tooling.report.ChartSpec.Format;
import org.jmclbench.tooling.report.ChartSpec.Kind;
import org.jmclbench.tooling.report.ChartSpec.Scale;
import org.jmclbench.tooling.report.ChartSpec.Series;
import org.jmclbench.tooling.report.ChartSpec.Setting;
import org.jmclbench.tooling.report.ChartSpec.Style;

import com.fasterxml.jackson.annotation.JsonIgnore;

/**
 * The report's charts, each built once from the aggregated cells by one method here: the page
 * draws these specifications and the export writes the same ones to SVG and PNG. A new chart is
 * one builder method and one {@link Figure} line (its heading and caption).
 */
final class ChartSpecs {

    /**
     * A figure of the page: its heading, caption, whether it is drawn per particle count (else
     * over the sweep of one policy) and the method that builds its chart. Whether its legend names
     * each runtime once is the chart's to say ({@link ChartSpec#legendPerRuntime}), which the page
     * and the exported files both read.
     */
    record Figure(String id, String heading, String caption, boolean perSetting,
                  @JsonIgnore Function<Scope, ChartSpec> builder) {
    }

    private static final String COMPLETION = "Every released job of every repetition merged: the fraction completed within "
            + "the response time on the x axis (end \u2212 release, ms, log). A dropped (skip) or aborted (terminate) job never "
            + "completes, so a runtime that drops work ends below 1 and cannot look faster for it.";
    private static final String MISS_RATIO = "Jobs not completed by their deadline (late + dropped + aborted) over the jobs "
            + "released, per run; mean over repetitions with its 95% interval cut at 0 and 1, on a log particle axis.";
    private static final String RESPONSE_P99 = "The 99th percentile of the response time (end \u2212 release, ms) over every "
            + "released job, a dropped or aborted job counting as +\u221e; mean over repetitions with its 95% interval cut at "
            + "0. A hollow triangle in the shaded band above the numbers, at the tick \u221e: the p99 of a repetition fell among "
            + "the jobs that never completed (+\u221e), which is no height; runtimes there at one count stand side by side.";

    /** The page's figures, in page order. */
    static final List<Figure> FIGURES = List.of(
            new Figure("misses", "The thesis\u2019s missCount vs particles: dropped (skip), dropped or aborted (terminate), late (queue) jobs", "missCount per run: the dropped jobs "
                    + "under skip, the dropped or aborted ones under terminate, the late ones under queue (a late job under skip is "
                    + "not counted; the miss-ratio charts count every deadline miss); mean over repetitions with 95% CI error bars "
                    + "(cut at 0: a count is never negative), per runtime. The thesis\u2019s histogram with errors.",
                    false, ChartSpecs::misses),
            new Figure("deviation", "Mean localisation deviation vs particles", "Mean Euclidean xy deviation of the estimate "
                    + "from the ground truth (m), mean over repetitions with 95% CI error bars (cut at 0: a distance is never negative).",
                    false, ChartSpecs::deviation),
            new Figure("latency-jitter", "Average task latency and release jitter vs particles", "Mean over the jobs that have "
                    + "the value, then over repetitions (ms), on a log particle axis. Solid: task latency (end \u2212 start), over "
                    + "the completed jobs; dashed: release jitter (start \u2212 release), over the started jobs.", false, ChartSpecs::latencyJitter),
            new Figure("memory", "Memory areas: peak bytes per engine and memory style", "The memory-model experiment at a "
                    + "glance: for each runtime, engine and memory style, the peak use of each memory area (bytes, log axis; the "
                    + "largest over the repetitions); the table gives the peaks and the mean bytes one release allocated in the area "
                    + "(heap: per job of the measured run). Java SE: the heap, a GC heap. SCJ: immortal and mission memory, and "
                    + "each handler\u2019s private memory, whose peak is that of one release (0 under the axis: the release "
                    + "allocated nothing, as the preallocated style promises); on a JVM these areas are budgets kept on its heap, "
                    + "on the HVM real areas. Hover a bar for the area\u2019s size and the bytes allocated per release. The native "
                    + "baseline reports no areas.", true, ChartSpecs::memory),
            new Figure("memory-release", "Memory areas: bytes allocated per release", "What one release allocates in each "
                    + "area (mean over the repetitions, bytes, log axis; a \u201c0\u201d under the axis: nothing), beside the "
                    + "peaks above. The areas are different things: the Java SE engine\u2019s heap is a GC heap (its bytes per "
                    + "release are per job of the measured run); the SCJ engine\u2019s immortal, mission and private memories are "
                    + "budgets kept on the JVM\u2019s GC heap on a JVM, and real memory areas with no collector only on the HVM.",
                    true, ChartSpecs::memoryPerRelease),
            new Figure("causes", "Why deadlines were missed", "Jobs missed or late per run (mean over the attributed "
                    + "repetitions), split by each job\u2019s largest cause (the primary cause of ./jmclbench explain): gc, "
                    + "safepoint, jit, os, preemption, compute, queued, overlap, unknown. Runs without attribution evidence are "
                    + "left out; a runtime that left some says under its bar how many of its runs were attributed.", true,
                    ChartSpecs::causes),
            new Figure("latency-index", "Task latency vs event index", "Every job of the first repetition (down-sampled): "
                    + "predict (odometry, every 50 ms) as dots, update (laser) as triangles. The thesis\u2019s XY points graph. "
                    + "Shaded bands: the GC (red) and safepoint (violet) pauses of that repetition of the first runtime shown "
                    + "that has some, placed on the event index through the jobs\u2019 release times.", true,
                    ChartSpecs::latencyIndex),
            new Figure("deviation-time", "Deviation over time, repeated runs", "Euclidean xy deviation (m) over the run, one "
                    + "line per repetition (up to five) per runtime. The thesis\u2019s XY lines graph.", true,
                    ChartSpecs::deviationTime),
            new Figure("trajectory", "Estimated vs real trajectory", "On the playground (dashed frame, metres); black: ground "
                    + "truth; triangles: the beacons; one estimate per runtime (first repetition).", true, ChartSpecs::trajectory),
            new Figure("spectrum", "Task latency percentile spectrum (completed jobs)", "HdrHistogram style: every completed "
                    + "job (done or late; a dropped or aborted job has no task latency) of every repetition merged; x = 1/(1\u2212p) on a log axis (10 = 90%, 100 = 99%, 1000 = 99.9%), latency (ms) on a log axis. "
                    + "Each curve ends at p = 1 \u2212 1/n for its n jobs: past it n jobs say nothing more.",
                    true, ChartSpecs::spectrum),
            new Figure("completion-predict", "Predict: fraction of released jobs completed by a response time", COMPLETION
                    + " Predict\u2019s deadline is 50 ms.", true, s -> TaskCharts.responseCompletion(s, "predict")),
            new Figure("completion-update", "Update: fraction of released jobs completed by a response time", COMPLETION
                    + " Update\u2019s deadline is the next laser event (32 to 250 ms on the match datasets).", true,
                    s -> TaskCharts.responseCompletion(s, "update")),
            vsParticles("Predict", TaskMetric.MISS_RATIO, MISS_RATIO),
            vsParticles("Update", TaskMetric.MISS_RATIO, MISS_RATIO),
            vsParticles("Predict", TaskMetric.RESPONSE_P99, RESPONSE_P99),
            vsParticles("Update", TaskMetric.RESPONSE_P99, RESPONSE_P99),
            new Figure("accuracy", "Accuracy vs timeliness of the policies", "At this particle count, one point per runtime "
                    + "and policy (every policy of the store, whichever is chosen above): x, the miss ratio over both tasks "
                    + "(late + dropped + aborted jobs over released ones); y, the mean localisation deviation (m); 95% intervals "
                    + "both ways, cut at 0 (and the ratio\u2019s at 1). Shape: skip circle, terminate triangle, queue square; "
                    + "colour: the runtime. Down and to the left is better.", true, s -> TaskCharts.accuracyVsTimeliness(s.acrossPolicies())),
            new Figure("conditions-load", "Idle vs loaded machine: miss ratio", "Per configuration, one bar per load scenario "
                    + "it ran under (none: an idle machine; cpu, alloc: docs/RUNNER.md), the miss ratio over both tasks, mean with "
                    + "its 95% interval cut at 0 and 1. A store run on an idle machine only has one bar per configuration.", true,
                    s -> TaskCharts.conditions(s, "conditions-load", "Miss ratio by load scenario", TaskMetric.MISS_RATIO, "all",
                            c -> c.loadCondition)),
            new Figure("abort-latency", "Abort latency (terminate)", "From the abort request (a later release: the gate\u2019s "
                    + "request, or the AIE fired at the job) to the aborted job\u2019s end, over every job an abort took hold of "
                    + "(the abort_ns column of the job files), every repetition merged; x = 1/(1\u2212p) on a log axis, latency "
                    + "(ms) on a log axis. A cooperative job ends at its next poll; the rtsj thesis design runs the job to its end "
                    + "(the AIE deferred in the robot\u2019s monitor). Dashed, in the runtime\u2019s colour: the static bound of "
                    + "./jmclbench verify, the longest gap between two abort points in particle steps times the runs\u2019 costliest "
                    + "particle step (the slowest job over its particles), or the slowest job where nothing bounds the gap.",
                    true, ChartSpecs::abortLatency),
            new Figure("breakdown", "Breakdown load (queue)", "Per runtime, the largest particle count at which every job of "
                    + "both tasks completed by its deadline in every repetition under queue, every smaller count of the store "
                    + "holding too (hover: the smallest count that did not). Only under the queue policy, where no job is dropped: "
                    + "the capacity command searches it (docs/RUNNER.md).", false, ChartSpecs::breakdown),
            new Figure("jitter-cdf", "CDF of release jitter (started jobs)", "Fraction of the started jobs released with at most "
                    + "the given jitter (ms, log axis), every started job (aborted ones included; a dropped job never starts, so it "
                    + "has no jitter) of every repetition merged.", true, ChartSpecs::jitterCdf));

    /** The figure of {@link TaskCharts#vsParticlesPerTask}: "Predict: miss ratio vs particles". */
    private static Figure vsParticles(String task, TaskMetric m, String caption) {
        String t = task.toLowerCase(Locale.ROOT);
        return new Figure(TaskCharts.perTaskId(m, t), task + ": " + m.label + " vs particles", caption, false,
                s -> TaskCharts.vsParticlesPerTask(s, t, m));
    }

    /**
     * What one chart is built from: the model (runtime colours and order, playgrounds), where in
     * the store the chart is, and the cells it shows.
     */
    record Scope(ReportModel model, Setting setting, List<ReportModel.Cell> cells) {

        /** The same setting with the cells of every policy of the store at its dataset and particle count. */
        Scope acrossPolicies() {
            return new Scope(model, setting, model.cells.stream().filter(c -> c.dataset.equals(setting.dataset())
                    && setting.particles() != null && c.particles == setting.particles()).toList());
        }

        /** The same setting with the cells {@code keep} accepts (the HVM alone, say, in its own panel). */
        Scope where(java.util.function.Predicate<ReportModel.Cell> keep) {
            return new Scope(model, setting, cells.stream().filter(keep).toList());
        }

        /** Whether a cell's runtime is the HVM, whose interpreted scale would hide the others' in a shared panel. */
        boolean hvm(ReportModel.Cell c) {
            return model.configs.stream().anyMatch(i -> i.id().equals(c.config) && i.kind() == org.jmclbench.tooling.runtime.RuntimeKind.HVM);
        }

        /** "dataset, policy[, N particles]", the end of every title. */
        String where() {
            return setting.dataset() + ", " + setting.policy() + (setting.particles() == null ? "" : ", " + setting.particles() + " particles");
        }

        /** The file name stem: names from the store reduced to safe file-name characters. */
        String stem(String id) {
            return safe(setting.dataset()) + "-" + safe(setting.policy())
                    + (setting.particles() == null ? "" : "-" + setting.particles()) + "-" + id;
        }

        String color(String config) {
            return model.configs.stream().filter(c -> c.id().equals(config)).map(ReportModel.ConfigInfo::color).findFirst()
                    .orElse("#7f7f7f");
        }

        /** The cells in the order of the legend (the model's runtime order). */
        List<ReportModel.Cell> ordered() {
            List<String> ids = model.configs.stream().map(ReportModel.ConfigInfo::id).toList();
            return cells.stream().sorted(Comparator.comparingInt((ReportModel.Cell c) -> ids.indexOf(c.config))
                    .thenComparingInt(c -> c.particles)).toList();
        }

        /** The configurations of the cells, in legend order, each with the engine of its first cell. */
        Map<String, String> configs() {
            Map<String, String> out = new LinkedHashMap<>();
            ordered().forEach(c -> out.putIfAbsent(c.config, c.engine));
            return out;
        }

        ChartSpec spec(String id, String title, Kind kind, boolean horizontal, Axis x, Axis y, List<Category> categories,
                       List<Series> series) {
            return new ChartSpec(id, stem(id), setting, title + " (" + where() + ")", kind, horizontal, x, y, categories, series,
                    List.of(), null, false);
        }
    }

    private ChartSpecs() {
    }

    /** Every figure at every setting of the store that has runs: the page's charts and the exported files. */
    static List<ChartSpec> all(ReportModel model) {
        List<ChartSpec> out = new ArrayList<>();
        for (String dataset : model.datasets) {
            for (String policy : model.policies) {
                List<ReportModel.Cell> cells = model.cells.stream()
                        .filter(c -> c.dataset.equals(dataset) && c.policy.equals(policy)).toList();
                if (cells.isEmpty()) {
                    continue;
                }
                Scope sweep = new Scope(model, new Setting(dataset, policy, null), cells);
                FIGURES.stream().filter(f -> !f.perSetting()).map(f -> f.builder().apply(sweep)).filter(Objects::nonNull)
                        .forEach(out::add);
                for (Integer particles : model.particles) {
                    List<ReportModel.Cell> at = cells.stream().filter(c -> c.particles == particles).toList();
                    if (!at.isEmpty()) {
                        Scope s = new Scope(model, new Setting(dataset, policy, particles), at);
                        FIGURES.stream().filter(Figure::perSetting).map(f -> f.builder().apply(s)).filter(Objects::nonNull)
                                .forEach(out::add);
                    }
                }
            }
        }
        return out;
    }

    static String safe(String s) {
        String t = s.replaceAll("[^A-Za-z0-9._-]", "_");
        return t.isEmpty() || t.startsWith(".") ? "_" + t : t;
    }

    // ---------------------------------------------------------------- over the particle sweep

    static ChartSpec misses(Scope s) {
        String jobs = Metric.missCountJobs(s.setting().policy());
        return vsParticles(s, "misses", Character.toUpperCase(jobs.charAt(0)) + jobs.substring(1) + " vs particles",
                jobs + " per run (the thesis's missCount, mean, 95% CI)", Metric.MISS_COUNT);
    }

    static ChartSpec deviation(Scope s) {
        return vsParticles(s, "deviation", "Mean deviation vs particles", "deviation xy (m, mean, 95% CI)", Metric.DEVIATION);
    }

    /** Bars per particle count, one per runtime, with the 95% bootstrap interval of the mean (within the runs' range: never below zero). */
    private static ChartSpec vsParticles(Scope s, String id, String title, String yLabel, Metric metric) {
        List<Integer> counts = s.cells().stream().map(c -> c.particles).distinct().sorted().toList();
        List<Series> series = new ArrayList<>();
        s.configs().forEach((config, engine) -> {
            List<Double> values = new ArrayList<>();
            List<double[]> errors = new ArrayList<>();
            for (int n : counts) {
                ReportModel.Agg a = s.cells().stream().filter(c -> c.config.equals(config) && c.particles == n)
                        .map(c -> c.metrics.get(metric.name())).findFirst().orElse(null);
                boolean has = a != null && a.mean() != null;
                values.add(has ? a.mean() : null);
                errors.add(has && a.low() != null ? new double[] {a.low(), a.high()} : null);
            }
            if (values.stream().anyMatch(v -> v != null)) {
                series.add(new Series(config, config, engine, s.color(config), Style.BAR, null, values, errors, null, null));
            }
        });
        return s.spec(id, title, Kind.BARS, false, Axis.linear("particles"), Axis.linear(yLabel).range(0.0, null),
                counts.stream().map(n -> new Category(String.valueOf(n), null, null)).toList(), series);
    }

    static ChartSpec latencyJitter(Scope s) {
        List<Series> series = new ArrayList<>();
        Style solid = new Style(true, 1.5, null, false, "circle", 3, null);
        s.configs().forEach((config, engine) -> {
            List<ReportModel.Cell> mine = s.ordered().stream().filter(c -> c.config.equals(config)).toList();
            addIfAny(series, new Series(config + " task latency", config, engine, s.color(config), solid,
                    metricPoints(mine, Metric.LATENCY_MEAN), null, null, null, null));
            addIfAny(series, new Series(config + " release jitter", config, engine, s.color(config), solid.dashed(6, 4),
                    metricPoints(mine, Metric.JITTER_MEAN), null, null, null, null));
        });
        return s.spec("latency-jitter", "Average task latency and release jitter vs particles", Kind.LINES, false,
                new Axis("particles (log)", Scale.LOG, Format.NUMBER, null, null),
                Axis.linear("time (ms, mean over repetitions; dashed: release jitter)"), null, series)
                .withLegendPerRuntime(); // the caption tells latency from jitter: one entry a runtime
    }

    private static List<double[]> metricPoints(List<ReportModel.Cell> cells, Metric m) {
        return cells.stream().filter(c -> c.metrics.get(m.name()).mean() != null)
                .map(c -> new double[] {c.particles, c.metrics.get(m.name()).mean()}).toList();
    }

    // ---------------------------------------------------------------- at one particle count

    /**
     * Grouped bars on a log axis: per row (runtime, engine, memory style), the peak bytes of each
     * memory area; a peak of 0 is a value of 0 (no bar on a log axis, a mark under it).
     */
    static ChartSpec memory(Scope s) {
        return areaBars(s, "memory", "Peak bytes per memory area", "peak bytes (log)", a -> a.peakBytes() == null ? null
                : a.peakBytes().doubleValue());
    }

    /**
     * Grouped bars on a log axis: per row, the mean bytes one release allocated in each memory
     * area (the heap: per job of the measured run), 0 drawn as a "0" under the axis: what tells a
     * preallocated style from an allocating one when the peaks are alike.
     */
    static ChartSpec memoryPerRelease(Scope s) {
        return areaBars(s, "memory-release", "Bytes allocated per release per memory area (SCJ budgets on a JVM heap, "
                + "real HVM areas and a GC heap are different things)", "bytes per release (log; 0 under the axis)",
                ReportModel.MemoryArea::bytesPerRelease);
    }

    private static ChartSpec areaBars(Scope s, String id, String title, String axis, Function<ReportModel.MemoryArea, Double> value) {
        List<ReportModel.Cell> rows = s.ordered().stream().filter(c -> !c.memoryAreas.isEmpty()).toList();
        List<String> names = new ArrayList<>();
        rows.forEach(c -> c.memoryAreas.stream().map(ReportModel.MemoryArea::name).filter(n -> !names.contains(n)).forEach(names::add));
        names.sort(Comparator.comparingInt(ReportModel::areaRank));
        List<Series> series = new ArrayList<>();
        int privateIndex = 0;
        for (String n : names) {
            List<Double> values = new ArrayList<>();
            List<String> notes = new ArrayList<>();
            for (ReportModel.Cell c : rows) {
                ReportModel.MemoryArea a = c.memoryAreas.stream().filter(x -> x.name().equals(n)).findFirst().orElse(null);
                values.add(a == null ? null : value.apply(a));
                notes.add(a == null ? null : n + ": peak " + ChartFormats.bytes(a.peakBytes())
                        + (a.size() == null ? "" : " of " + ChartFormats.bytes(a.size()))
                        + (a.bytesPerRelease() == null ? "" : ", " + ChartFormats.bytes(a.bytesPerRelease()) + " per release")
                        + (a.allocatingReleases() == null ? "" : ", " + a.allocatingReleases() + " of " + a.releases() + " releases allocated"));
            }
            String color = Palette.area(n, Palette.AREA_COLORS.containsKey(n) ? 0 : privateIndex++);
            series.add(new Series(n, null, null, color, Style.BAR, null, values, null, null, notes));
        }
        double smallest = series.stream().flatMap(x -> x.values().stream()).filter(v -> v != null && v > 0)
                .mapToDouble(Double::doubleValue).min().orElse(1.0);
        double lo = logFloor(smallest);
        Axis y = rows.isEmpty() ? Axis.linear(axis + ": no memory areas reported")
                : new Axis(axis, Scale.LOG, Format.BYTES, lo, null);
        return s.spec(id, title, Kind.BARS, false, Axis.linear("runtime / engine memory style"), y, categories(rows), series);
    }

    /**
     * A log bar axis's lower end: 1, or the power of ten strictly under the smallest value (a mean
     * of 72 B in one release of 200 is 0.36 B), so that every bar has a height; from 1 B, a bar
     * of 1 B per release had none and read as no value.
     */
    static double logFloor(double smallest) {
        return Math.min(1.0, Math.pow(10, Math.ceil(Math.log10(smallest)) - 1));
    }

    /** Stacked bars across: per runtime, the jobs missed or late per run by primary cause, in the causes' fixed colours. */
    static ChartSpec causes(Scope s) {
        List<ReportModel.Cell> rows = s.ordered().stream().filter(c -> !c.causes.isEmpty()).toList();
        List<String> kinds = new ArrayList<>(Palette.CAUSE_COLORS.keySet());
        rows.stream().flatMap(c -> c.causes.keySet().stream()).filter(k -> !kinds.contains(k)).distinct().sorted().forEach(kinds::add);
        List<Series> series = new ArrayList<>();
        for (String k : kinds) {
            // a cause recorded but never a job's primary one draws no segment: no legend entry either
            if (rows.stream().anyMatch(c -> c.causes.getOrDefault(k, 0.0) > 0)) {
                List<Double> values = rows.stream().map(c -> c.causes.get(k)).toList();
                series.add(new Series(k, null, null, Palette.CAUSE_COLORS.getOrDefault(k, Palette.color(series.size())),
                        Style.BAR, null, values, null, null, null));
            }
        }
        // a runtime that left some runs without evidence: its bar is a mean over fewer runs, and says so
        List<Category> categories = rows.stream().map(c -> new Category(c.attributedRuns < c.ok
                ? c.config + " (" + c.attributedRuns + " of " + c.ok + " runs attributed)" : c.config, c.config, c.engine)).toList();
        return s.spec("causes", "Why deadlines were missed", Kind.STACKED_BARS, true, Axis.linear("runtime/profile"),
                Axis.linear("jobs missed or late per run, by primary cause (mean)").range(0.0, null), categories, series);
    }

    /** Every job of the first repetition, predict as dots and update as hollow triangles, with the runs' pauses as bands. */
    static ChartSpec latencyIndex(Scope s) {
        List<Series> series = new ArrayList<>();
        List<Band> bands = new ArrayList<>();
        for (ReportModel.Cell c : s.ordered()) {
            addIfAny(series, new Series(c.config + " predict", c.config, c.engine, s.color(c.config), Style.marks("circle", 2, null),
                    c.latencyPredict, null, null, null, null));
            addIfAny(series, new Series(c.config + " update", c.config, c.engine, s.color(c.config), Style.marks("triangle", 3, "none"),
                    c.latencyUpdate, null, null, null, null));
            for (int i = 0; i < c.pauses.size(); i++) {
                String kind = c.pauseKinds.get(i);
                bands.add(new Band(c.pauses.get(i)[0], c.pauses.get(i)[1], kind, Palette.bandColor(kind), c.config));
            }
        }
        return s.spec("latency-index", "Task latency vs event index", Kind.LINES, false, Axis.linear("event index"),
                Axis.linear("task latency (ms); dots: predict, triangles: update"), null, series).behind(bands, null)
                .withLegendPerRuntime(); // the caption tells predict from update

    }

    static ChartSpec deviationTime(Scope s) {
        List<Series> series = new ArrayList<>();
        for (ReportModel.Cell c : s.ordered()) {
            for (int i = 0; i < c.deviation.size(); i++) {
                Style st = i == 0 ? Style.line(1.2) : Style.line(1.2).dashed(2 + i, 2); // the first repetition solid
                addIfAny(series, new Series(c.config + " #" + c.deviationRepetitions.get(i), c.config, c.engine, s.color(c.config),
                        st, c.deviation.get(i), null, null, null, null));
            }
        }
        return s.spec("deviation-time", "Deviation over time, repeated runs", Kind.LINES, false, Axis.linear("time (s)"),
                Axis.linear("deviation xy (m)"), null, series).withLegendPerRuntime(); // the caption tells the repetitions apart
    }

    /** The ground truth, one estimate per runtime and the beacons, on the dataset's playground. */
    static ChartSpec trajectory(Scope s) {
        // both renderers draw the first series on top: the beacons, then the estimates, then the
        // ground truth under them all (on top, its thick line hid every estimate that tracked it)
        List<Series> series = new ArrayList<>();
        ReportModel.Playground pg = s.model().playgrounds.getOrDefault(s.setting().dataset(), ReportModel.Playground.thesis());
        series.add(new Series("beacons", null, null, "#000000", Style.marks("triangle", 9, "#ffd400"), pg.beacons(), null, null,
                null, null));
        for (ReportModel.Cell c : s.ordered()) {
            addIfAny(series, new Series(c.config + " estimate", c.config, c.engine, s.color(c.config), Style.line(1.2), c.trajectory,
                    null, null, null, null));
        }
        s.ordered().stream().filter(c -> !c.real.isEmpty()).findFirst().ifPresent(c ->
                series.add(new Series("real", null, null, "#000000", Style.line(2.5), c.real, null, null, null, null)));
        double m = 0.15;
        return s.spec("trajectory", "Estimated vs real trajectory", Kind.LINES, false,
                Axis.linear("x (m)").range(-m, pg.width() + m), Axis.linear("y (m)").range(-m, pg.height() + m), null, series)
                .behind(List.of(), new ChartSpec.Frame(pg.width(), pg.height()));
    }

    static ChartSpec spectrum(Scope s) {
        return percentiles(s, "spectrum", "Task latency by percentile, completed jobs of all repetitions",
                "task latency (ms, log)",
                c -> c.latencySpectrum);
    }

    /** The abort latency spectrum per runtime; null where no run had an abort take hold (every policy but terminate). */
    static ChartSpec abortLatency(Scope s) {
        ChartSpec c = percentiles(s, "abort-latency", "Abort latency by percentile, every job an abort took hold of, all repetitions",
                "abort latency (ms, log)", cell -> cell.abortSpectrum);
        if (c.series().isEmpty()) {
            return null;
        }
        // verify's static bound beside each measured spectrum: a dashed line in the runtime's colour
        List<Series> series = new ArrayList<>(c.series());
        for (ReportModel.Cell cell : s.ordered()) {
            AbortBounds.Bound b = s.model().abortBounds.of(cell, s.model());
            Double ms = b == null || cell.abortSpectrum.isEmpty() ? null : b.millis(cell);
            if (ms != null) {
                double right = cell.abortSpectrum.get(cell.abortSpectrum.size() - 1)[0];
                series.add(new Series(cell.config + " static bound (" + b.span() + ")", cell.config, cell.engine,
                        s.color(cell.config), Style.line(1.2).dashed(6, 4), List.of(new double[] {1, ms}, new double[] {right, ms}),
                        null, null, null, null));
            }
        }
        if (series.size() == c.series().size()) {
            // the caption promises dashed bounds: a chart without them says why
            return c.withSeries(series).withTitle(c.title() + "; no static bound drawn: " + (s.model().abortBounds == AbortBounds.NONE
                    ? "no verify results (" + VerificationSection.FILE + ") beside the store" : "verify bounds none of these jobs"));
        }
        return c.withSeries(series);
    }

    /** One line per runtime of [1/(1-p), ms, p] points, both axes log. */
    private static ChartSpec percentiles(Scope s, String id, String title, String yLabel,
                                         Function<ReportModel.Cell, List<double[]>> points) {
        List<Series> series = new ArrayList<>();
        for (ReportModel.Cell c : s.ordered()) {
            List<double[]> pts = points.apply(c).stream().map(p -> new double[] {p[0], Math.max(p[1], 1e-4)}).toList();
            // one job (one abort, say) is one point: a line without a mark would draw nothing at all
            Style style = pts.size() == 1 ? new Style(true, 1.5, null, false, "circle", 4, null) : Style.line(1.5);
            addIfAny(series, new Series(c.config, c.config, c.engine, s.color(c.config), style, pts, null, null, null, null));
        }
        return s.spec(id, title, Kind.LINES, false,
                new Axis("percentile (log scale of 1/(1\u2212p))", Scale.LOG, Format.PERCENTILE, 1.0, null),
                new Axis(yLabel, Scale.LOG, Format.NUMBER, null, null), null, series);
    }

    static ChartSpec jitterCdf(Scope s) {
        List<Series> series = new ArrayList<>();
        for (ReportModel.Cell c : s.ordered()) {
            addIfAny(series, new Series(c.config, c.config, c.engine, s.color(c.config), Style.line(1.5).steps(), c.jitterCdf, null,
                    null, null, null));
        }
        return s.spec("jitter-cdf", "CDF of release jitter, started jobs of all repetitions", Kind.LINES, false,
                new Axis("release jitter (ms, log)", Scale.LOG, Format.NUMBER, null, null),
                Axis.linear("fraction of started jobs").range(0.0, 1.0), null, series);
    }

    /**
     * Bars across, one per runtime in its colour: the largest particle count it sustained with no
     * miss, written at the bar's end; no bar where even the smallest count missed (null), its name
     * then saying so: a bar of 0 read as a breakdown load of 0. The evaluation's.
     */
    static ChartSpec sustained(Scope s, String id, String title, Map<String, Integer> loads) {
        return loadBars(s, id, title, "largest particle count with no miss", loads, null);
    }

    /** The breakdown load of each runtime under queue ({@link BreakdownLoad}); null at any other policy. */
    static ChartSpec breakdown(Scope s) {
        if (!s.setting().policy().equals("queue")) {
            return null;
        }
        Map<String, BreakdownLoad> loads = BreakdownLoad.of(s.cells(), new ArrayList<>(s.configs().keySet()));
        Map<String, Integer> holds = new LinkedHashMap<>();
        List<String> notes = new ArrayList<>();
        loads.forEach((config, b) -> {
            holds.put(config, b.holds());
            notes.add(config + ": holds at " + (b.holds() == null ? "no count" : b.holds())
                    + ", fails at " + (b.fails() == null ? "no count of the store" : b.fails())
                    + (b.failedRuns() != null ? " (" + b.failedRuns() + ")" : b.late() != null ? " (" + b.late() + ")" : ""));
        });
        return loadBars(s, "breakdown", "Breakdown load: every job by its deadline (" + s.where() + ")",
                "largest particle count with no late job", holds, notes).withStem(s.stem("breakdown"));
    }

    private static ChartSpec loadBars(Scope s, String id, String title, String axis, Map<String, Integer> loads, List<String> notes) {
        List<String> configs = new ArrayList<>(loads.keySet());
        Series bars = new Series("particles", null, null, "#7f7f7f", Style.BAR, null,
                configs.stream().map(c -> loads.get(c) == null ? null : (Double) loads.get(c).doubleValue()).toList(), null,
                configs.stream().map(s::color).toList(), notes);
        List<Category> categories = configs.stream()
                .map(c -> new Category(loads.get(c) == null ? c + " (held at no count)" : c, c, s.configs().get(c))).toList();
        return new ChartSpec(id, id, s.setting(), title,
                Kind.BARS, true, Axis.linear("runtime / engine memory style"), Axis.linear(axis), categories, List.of(bars),
                List.of(), null, true);
    }

    private static List<Category> categories(List<ReportModel.Cell> rows) {
        return rows.stream().map(c -> new Category(c.config, c.config, c.engine)).toList();
    }

    private static void addIfAny(List<Series> series, Series s) {
        if (s.points() != null && !s.points().isEmpty()) {
            series.add(s);
        }
    }
}
