package org.jmclbench.tooling.report;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.stream.Collectors;

import org.jmclbench.tooling.store.StoredRun;
import org.jmclbench.tooling.store.StoredRuns;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The per-task charts on a fixture store of three policies, two scheduling profiles and two load
 * scenarios: each chart's points are the cells' numbers (checked against the runs' summaries),
 * intervals never leave [0, 1] for a ratio or go below 0, and a store without response-time
 * histograms leaves the completion curves out without failing.
 */
class TaskChartsTest {

    static final String DEFAULT = "temurin-25/default";
    static final String PINNED = "temurin-25/fifo+pinned";

    @TempDir
    static Path dir;
    static ReportModel model;
    static List<StoredRun> runs;

    @BeforeAll
    static void build() throws Exception {
        FixtureDb f = new FixtureDb();
        f.configs = new ArrayList<>(List.of(new FixtureDb.Config("native", "", "gcc 12.2.0", 1.0, "ok"),
                new FixtureDb.Config("temurin-25", "default", "25+36", 1.2, "ok"),
                new FixtureDb.Config("temurin-25", "fifo+pinned", "25+36", 1.1, "ok")));
        f.policies = List.of("skip", "terminate", "queue");
        f.particles = List.of(100, 1600);
        f.loads = List.of("none", "cpu");
        f.repetitions = 3;
        f.durationS = 6;
        Path db = ReportFixtures.write(f, dir, "tasks.db");
        try (StoredRuns store = StoredRuns.open(db, "--db")) {
            model = ReportModel.build(store, line -> { });
            runs = store.runs();
        }
    }

    static ChartSpecs.Scope scope(String policy, Integer particles) {
        return new ChartSpecs.Scope(model, new ChartSpec.Setting("match-short", policy, particles), model.cells.stream()
                .filter(c -> c.policy.equals(policy) && (particles == null || c.particles == particles)).toList());
    }

    static ReportModel.Cell cell(String config, String policy, int particles) {
        return model.cells.stream().filter(c -> c.config.equals(config) && c.policy.equals(policy) && c.particles == particles)
                .findFirst().orElseThrow();
    }

    static List<StoredRun> runsOf(ReportModel.Cell c) {
        return runs.stream().filter(r -> r.ok() && r.configOnMachine().equals(c.config) && r.policy.equals(c.policy)
                && r.particles == c.particles).toList();
    }

    static ChartSpec.Series series(ChartSpec spec, String name) {
        return spec.series().stream().filter(s -> s.name().equals(name)).findFirst().orElseThrow(() -> new AssertionError(name
                + " not in " + spec.series().stream().map(ChartSpec.Series::name).toList()));
    }

    @Test
    void runsUnderTwoLoadsAreTwoConfigurationsNeverPooled() {
        assertEquals(List.of("native", "native [load cpu]", DEFAULT, DEFAULT + " [load cpu]", PINNED, PINNED + " [load cpu]"),
                model.configs.stream().map(ReportModel.ConfigInfo::id).toList(), "an idle machine's runs keep the plain name");
        ReportModel.Cell c = cell(DEFAULT + " [load cpu]", "skip", 100);
        assertEquals("cpu", c.load);
        assertEquals("temurin-25", c.runtime);
        assertEquals("default", c.profile);
        assertEquals(3, c.ok, "the three repetitions under cpu load, not the idle ones too");
    }

    @Test
    void perTaskMetricsAreTheMeansOfTheRunsSummaries() {
        for (ReportModel.Cell c : model.cells) {
            List<StoredRun> mine = runsOf(c);
            assertEquals(3, mine.size());
            for (String task : List.of("predict", "update", "all")) {
                double ratio = mine.stream().mapToDouble(r -> r.summary().at("/tasks/" + task + "/missRatio").asDouble()).average()
                        .orElseThrow();
                assertEquals(ratio, c.metrics.get(TaskMetric.MISS_RATIO.key(task)).mean(), 1e-12, c.config + " " + task);
                double dropped = mine.stream().mapToDouble(r -> r.summary().at("/tasks/" + task + "/skipped").asDouble()).average()
                        .orElseThrow();
                assertEquals(dropped, c.metrics.get(TaskMetric.DROPPED.key(task)).mean(), 1e-12);
                boolean anyInf = mine.stream().anyMatch(r -> r.summary().at("/tasks/" + task + "/responseTimeReleasedNs/p99").isTextual());
                ReportModel.Agg p99 = c.metrics.get(TaskMetric.RESPONSE_P99.key(task));
                if (anyInf) {
                    assertEquals(Double.POSITIVE_INFINITY, p99.mean(), "a p99 among the dropped jobs is +inf, not left out");
                    assertNull(p99.low());
                } else {
                    double mean = mine.stream().mapToDouble(r -> r.summary().at("/tasks/" + task + "/responseTimeReleasedNs/p99")
                            .asDouble() / 1e6).average().orElseThrow();
                    assertEquals(mean, p99.mean(), 1e-9);
                }
            }
        }
        assertTrue(model.cells.stream().anyMatch(c -> c.metrics.get(TaskMetric.RESPONSE_P99.key("predict")).mean().isInfinite()),
                "the fixture drops more than 1% of predict's jobs somewhere");
        assertTrue(model.cells.stream().anyMatch(c -> Double.isFinite(c.metrics.get(TaskMetric.RESPONSE_P99.key("predict")).mean())));
    }

    @Test
    void aRunBeforeDeadlineAccountingGetsItFromItsDefinitionAndTheMetricsTableComesFirst() {
        StoredRun r = new StoredRun();
        r.status = "ok";
        r.summaryJson = "{\"tasks\": {\"update\": {\"released\": 40, \"late\": 1, \"skipped\": 2, \"terminated\": 1,"
                + " \"responseTimeReleasedNs\": {\"p50\": 2000000, \"max\": \"inf\"}}}}";
        assertEquals(4.0, TaskMetric.DEADLINE_MISSES.of(r, "update"));
        assertEquals(0.1, TaskMetric.MISS_RATIO.of(r, "update"), 1e-12);
        assertEquals(2.0, TaskMetric.RESPONSE_P50.of(r, "update"), 1e-12);
        assertEquals(Double.POSITIVE_INFINITY, TaskMetric.RESPONSE_MAX.of(r, "update"));
        assertNull(TaskMetric.RESPONSE_P99.of(r, "update"), "not in the summary: no value, not zero");
        assertNull(TaskMetric.MISS_RATIO.of(r, "predict"));
        r.metrics.put("update/missRatio/value", 0.25);
        assertEquals(0.25, TaskMetric.MISS_RATIO.of(r, "update"), "the flattened metrics first");
        r.status = "failed";
        assertNull(TaskMetric.MISS_RATIO.of(r, "update"));
    }

    @Test
    void completionEndsAtTheFractionOfReleasedJobsThatCompleted() {
        ChartSpec spec = TaskCharts.responseCompletion(scope("skip", 1600), "predict");
        assertEquals("completion-predict", spec.id());
        assertEquals(6, spec.series().size(), "every configuration of the setting");
        for (ChartSpec.Series s : spec.series()) {
            ReportModel.Cell c = cell(s.config(), "skip", 1600);
            double released = runsOf(c).stream().mapToDouble(r -> r.summary().at("/tasks/predict/released").asDouble()).sum();
            double completed = runsOf(c).stream().mapToDouble(r -> r.summary().at("/tasks/predict/completed").asDouble()).sum();
            List<double[]> pts = s.points();
            assertEquals(completed / released, pts.get(pts.size() - 1)[1], 1e-5, s.name());
            assertEquals(0.0, pts.get(0)[1]);
            for (int i = 1; i < pts.size(); i++) {
                assertTrue(pts.get(i)[0] >= pts.get(i - 1)[0] && pts.get(i)[1] >= pts.get(i - 1)[1], s.name() + " at " + i);
            }
        }
        assertTrue(spec.series().stream().anyMatch(s -> s.points().get(s.points().size() - 1)[1] < 1),
                "a runtime that dropped jobs ends below 1");
        assertEquals(ChartSpec.Scale.LOG, spec.x().scale());
    }

    @Test
    void aStoreWithoutResponseHistogramsLeavesTheCurvesOutAndSaysSo() throws Exception {
        FixtureDb f = ReportFixtures.engines();
        f.responseHistograms = false;
        f.deadlineAccounting = false;
        Path db = ReportFixtures.write(f, dir, "old.db");
        try (StoredRuns store = StoredRuns.open(db, "--db")) {
            ReportModel old = ReportModel.build(store, line -> { });
            ChartSpec spec = TaskCharts.responseCompletion(new ChartSpecs.Scope(old, new ChartSpec.Setting("match-short", "skip", 400),
                    old.cells.stream().filter(c -> c.particles == 400).toList()), "update");
            assertTrue(spec.series().isEmpty());
            assertTrue(spec.title().contains("no response times stored for " + ReportFixtures.NATIVE), spec.title());
            // before the deadline accounting: the miss ratio from its definition, no response time over released jobs
            ChartSpecs.Scope sweep = new ChartSpecs.Scope(old, new ChartSpec.Setting("match-short", "skip", null), old.cells);
            ChartSpec ratio = TaskCharts.vsParticlesPerTask(sweep, "predict", TaskMetric.MISS_RATIO);
            assertEquals(5, ratio.series().size());
            assertTrue(ratio.series().stream().allMatch(s -> s.points().size() == 2));
            ChartSpec p99 = TaskCharts.vsParticlesPerTask(sweep, "predict", TaskMetric.RESPONSE_P99);
            assertTrue(p99.series().isEmpty());
            assertTrue(p99.title().contains("; no value for " + ReportFixtures.NATIVE + ", "), p99.title());
        }
    }

    @Test
    void perTaskLinesAreTheCellsMeansWithIntervalsInsideZeroToOne() {
        ChartSpec spec = TaskCharts.vsParticlesPerTask(scope("skip", null), "update", TaskMetric.MISS_RATIO);
        assertEquals("miss-ratio-update", spec.id());
        assertEquals(ChartSpec.Scale.LOG, spec.x().scale());
        assertEquals(6, spec.series().size());
        for (ChartSpec.Series s : spec.series()) {
            assertEquals(2, s.points().size());
            for (int i = 0; i < 2; i++) {
                ReportModel.Agg a = cell(s.config(), "skip", (int) s.points().get(i)[0]).metrics.get("update.MISS_RATIO");
                assertEquals(a.mean(), s.points().get(i)[1]);
                double[] e = s.errors().get(i);
                assertEquals(Math.max(0, a.low()), e[0], 1e-12);
                assertEquals(Math.min(1, a.high()), e[1], 1e-12);
            }
        }
        assertTrue(spec.series().stream().anyMatch(s -> s.errors().stream().anyMatch(e -> e[0] == 0)),
                "some interval reaches below zero and is cut there");
    }

    @Test
    void anInfiniteQuantileIsAMarkAtTheTopNotAMissingPoint() {
        ChartSpec spec = TaskCharts.vsParticlesPerTask(scope("skip", null), "predict", TaskMetric.RESPONSE_P99);
        double top = spec.series().stream().filter(s -> s.errors() != null).flatMap(s -> s.errors().stream())
                .mapToDouble(e -> e[1]).max().orElseThrow();
        ChartSpec.Beyond band = spec.y().beyond();
        assertTrue(band != null, "the chart has a band for +infinity");
        assertTrue(band.from() > top && band.at() > band.from() && spec.y().max() > band.at(),
                "the band lies above every number drawn, its marks inside it, under the axis' top");
        assertEquals("\u221e", band.tick(), "the band's tick reads infinity, not a number");
        assertTrue(band.label().contains("never completed"), band.label());
        int marks = 0;
        for (ReportModel.Cell c : scope("skip", null).cells()) {
            double mean = c.metrics.get("predict.RESPONSE_P99").mean();
            if (Double.isInfinite(mean)) {
                ChartSpec.Series inf = series(spec, c.config + " \u221e");
                assertTrue(inf.points().stream().anyMatch(p -> Math.abs(Math.log(p[0] / c.particles)) < Math.log(TaskCharts.SPREAD)
                        && p[1] == band.at()), c.config);
                assertEquals("triangle", inf.style().marker());
                marks++;
            } else {
                assertTrue(series(spec, c.config).points().stream().anyMatch(p -> p[0] == c.particles && p[1] == mean), c.config);
            }
        }
        assertTrue(marks > 0);
    }

    @Test
    void infiniteMarksOfSeveralRuntimesAtOneCountStandApart() {
        ChartSpec spec = TaskCharts.vsParticlesPerTask(scope("skip", null), "predict", TaskMetric.RESPONSE_P99);
        Map<String, List<Double>> xsAtCount = new java.util.TreeMap<>(); // per count (its note names it), the marks' x
        spec.series().stream().filter(s -> s.name().endsWith(" \u221e")).forEach(s -> {
            for (int i = 0; i < s.points().size(); i++) {
                String count = s.notes().get(i).replaceAll(".* at (\\d+) particles.*", "$1");
                xsAtCount.computeIfAbsent(count, k -> new ArrayList<>()).add(s.points().get(i)[0]);
            }
        });
        assertTrue(xsAtCount.values().stream().anyMatch(xs -> xs.size() > 1), "the fixture has two runtimes infinite at one count");
        for (List<Double> xs : xsAtCount.values()) {
            assertEquals(xs.size(), xs.stream().distinct().count(), "no mark drawn on another: " + xs);
        }
        assertEquals(1600, TaskCharts.spread(1600, 0, 1), 0);
        assertEquals(1600 * 1600, TaskCharts.spread(1600, 0, 3) * TaskCharts.spread(1600, 2, 3), 1e-6, "spread evenly around the count");
        assertTrue(TaskCharts.spread(1600, 9, 10) / TaskCharts.spread(1600, 0, 10) <= TaskCharts.SPREAD + 1e-9, "never far from it");
    }

    @Test
    void theLegendNamesEachRuntimeOnceInItsColourBesideTheInfinityBand() throws Exception {
        // the p99 charts' legends listed every runtime twice, "<config>" and "<config> \u221e", on the page and in the
        // files; the band's label says what the marks are, so a runtime is one entry in its one colour
        ChartSpec spec = TaskCharts.vsParticlesPerTask(scope("skip", null), "predict", TaskMetric.RESPONSE_P99);
        assertTrue(spec.y().beyond() != null && spec.series().stream().anyMatch(s -> s.name().endsWith(" \u221e")),
                "the fixture has +infinity marks: the test would prove nothing");
        assertTrue(spec.legendPerRuntime(), "the chart says its legend names each runtime once, for the page and the files");
        Map<String, String> colours = new java.util.LinkedHashMap<>();
        spec.series().forEach(s -> colours.putIfAbsent(s.config(), s.color()));
        org.jfree.chart.LegendItemCollection items = ChartExporter.render(spec).getXYPlot().getLegendItems();
        List<String> labels = new ArrayList<>();
        for (int i = 0; i < items.getItemCount(); i++) {
            String label = items.get(i).getLabel();
            labels.add(label);
            assertTrue(colours.containsKey(label), "the entry " + label + " names no runtime");
            assertEquals(ChartExporter.color(colours.get(label)), items.get(i).getLinePaint(), label);
        }
        assertEquals(new ArrayList<>(colours.keySet()), labels, "each runtime once, by its name");
        assertFalse(TaskCharts.vsParticlesPerTask(scope("skip", null), "predict", TaskMetric.MISS_RATIO).legendPerRuntime(),
                "a chart without the band names its series as before");
    }

    @Test
    void aChartWithoutInfinityHasNoBand() {
        ChartSpec spec = TaskCharts.vsParticlesPerTask(scope("skip", null), "predict", TaskMetric.MISS_RATIO);
        assertNull(spec.y().beyond());
        assertNull(spec.y().max());
    }

    @Test
    void accuracyHasOnePointPerConfigurationAndPolicyWithTheirIntervals() {
        ChartSpecs.Scope at = scope("skip", 1600).acrossPolicies();
        assertEquals(3 * 6, at.cells().size(), "the cells of every policy at the setting's count");
        ChartSpec spec = TaskCharts.accuracyVsTimeliness(at);
        assertEquals(18, spec.series().size());
        Map<String, String> markers = Map.of("skip", "circle", "terminate", "triangle", "queue", "square");
        for (ReportModel.Cell c : at.cells()) {
            ChartSpec.Series s = series(spec, c.config + " \u00b7 " + c.policy);
            assertEquals(c.metrics.get("all.MISS_RATIO").mean(), s.points().get(0)[0]);
            assertEquals(c.metrics.get("DEVIATION").mean(), s.points().get(0)[1]);
            assertEquals(markers.get(c.policy), s.style().marker());
            assertEquals(at.color(c.config), s.color(), "the runtime's colour");
            double[] x = s.xErrors().get(0);
            double[] y = s.errors().get(0);
            assertTrue(x[0] >= 0 && x[0] <= s.points().get(0)[0] && x[1] <= 1 && x[1] >= s.points().get(0)[0]);
            assertTrue(y[0] >= 0 && y[0] <= s.points().get(0)[1] && y[1] >= s.points().get(0)[1]);
        }
    }

    @Test
    void conditionsGroupEachConfigurationAcrossLoadsOrProfiles() {
        ChartSpecs.Scope s = scope("queue", 1600);
        ChartSpec load = TaskCharts.conditions(s, "load", "Misses by load", Metric.MISS_COUNT, c -> c.load);
        assertEquals(List.of("native", DEFAULT, PINNED), load.categories().stream().map(ChartSpec.Category::label).toList());
        assertEquals(List.of("none", "cpu"), load.series().stream().map(ChartSpec.Series::name).toList(), "the idle machine first");
        for (ChartSpec.Series cond : load.series()) {
            for (int i = 0; i < 3; i++) {
                String label = load.categories().get(i).label();
                ReportModel.Agg a = cell(cond.name().equals("none") ? label : label + " [load " + cond.name() + "]", "queue", 1600)
                        .metrics.get("MISS_COUNT");
                assertEquals(a.mean(), cond.values().get(i));
                assertEquals(Math.max(0, a.low()), cond.errors().get(i)[0], 1e-12);
            }
        }
        assertTrue(load.series().stream().noneMatch(x -> Palette.RUNTIME_COLORS.contains(x.color())),
                "a condition takes no runtime's colour");

        ChartSpec profile = TaskCharts.conditions(s, "profile", "Miss ratio by profile", TaskMetric.MISS_RATIO, "predict",
                c -> c.profile);
        assertEquals(List.of("native", "native [load cpu]", "temurin-25", "temurin-25 [load cpu]"),
                profile.categories().stream().map(ChartSpec.Category::label).toList());
        assertEquals(List.of("default", "fifo+pinned"), profile.series().stream().map(ChartSpec.Series::name).toList(),
                "native, without a profile, under default");
        ChartSpec.Series pinned = series(profile, "fifo+pinned");
        assertNull(pinned.values().get(0), "native has no fifo+pinned profile");
        assertEquals(cell(PINNED, "queue", 1600).metrics.get("predict.MISS_RATIO").mean(), pinned.values().get(2));
        assertEquals(cell(PINNED + " [load cpu]", "queue", 1600).metrics.get("predict.MISS_RATIO").mean(), pinned.values().get(3));
        assertEquals(cell("native", "queue", 1600).metrics.get("predict.MISS_RATIO").mean(),
                series(profile, "default").values().get(0));
    }

    @Test
    void theHvmGetsItsOwnPanel() throws Exception {
        FixtureDb f = ReportFixtures.engines();
        f.configs.add(new FixtureDb.Config("hvm", "", "icecap 4d31e23", 30.0, "ok", "scj", "scoped"));
        Path db = ReportFixtures.write(f, dir, "hvm.db");
        try (StoredRuns store = StoredRuns.open(db, "--db")) {
            ReportModel m = ReportModel.build(store, line -> { });
            ChartSpecs.Scope all = new ChartSpecs.Scope(m, new ChartSpec.Setting("match-short", "skip", null), m.cells);
            ChartSpec others = TaskCharts.vsParticlesPerTask(all.where(c -> !all.hvm(c)), "predict", TaskMetric.JITTER_P99);
            ChartSpec hvm = TaskCharts.vsParticlesPerTask(all.where(all::hvm), "predict", TaskMetric.JITTER_P99);
            assertEquals(List.of("hvm / scj scoped"), hvm.series().stream().map(ChartSpec.Series::name).toList());
            assertEquals(5, others.series().size());
            assertTrue(others.series().stream().noneMatch(s -> s.name().startsWith("hvm")));
            assertEquals(m.configs.stream().filter(c -> c.id().equals("hvm / scj scoped")).findFirst().orElseThrow().color(),
                    hvm.series().get(0).color(), "its colour is the one it has everywhere");
        }
    }

    @Test
    void theExporterDrawsPointsWithIntervalsBothWays() throws Exception {
        ChartExporter exporter = new ChartExporter(dir.resolve("charts"));
        for (ChartSpec spec : List.of(TaskCharts.accuracyVsTimeliness(scope("skip", 1600).acrossPolicies()),
                TaskCharts.vsParticlesPerTask(scope("skip", null), "predict", TaskMetric.RESPONSE_P99),
                TaskCharts.responseCompletion(scope("skip", 1600), "update"),
                TaskCharts.conditions(scope("queue", 1600), "load", "by load", Metric.DEVIATION, c -> c.load),
                TaskCharts.vsParticles(scope("skip", null), Metric.DEVIATION))) {
            exporter.write(spec);
            String svg = Files.readString(dir.resolve("charts/" + spec.stem() + ".svg"));
            for (ChartSpec.Series s : spec.series()) {
                String entry = spec.legendPerRuntime() ? s.config() : s.name(); // the +infinity marks under their runtime's entry
                assertTrue(svg.contains(">" + entry + "<"), entry + " in " + spec.stem());
                assertEquals(!spec.legendPerRuntime() || s.name().equals(s.config()), svg.contains(">" + s.name() + "<"),
                        s.name() + " named in " + spec.stem());
            }
        }
        // the error bars are drawn, one SVG path each: points both ways, bars with their cut intervals
        assertEquals(18 * 2, pathsOfErrors(exporter, TaskCharts.accuracyVsTimeliness(scope("skip", 1600).acrossPolicies())));
        assertEquals(3 * 2, pathsOfErrors(exporter, TaskCharts.conditions(scope("queue", 1600), "load", "by load", Metric.DEVIATION,
                c -> c.load)));
    }

    /** The SVG paths a chart's error bars add: those of the file with them less those of the file without. */
    static long pathsOfErrors(ChartExporter exporter, ChartSpec spec) throws Exception {
        List<ChartSpec.Series> bare = spec.series().stream().map(s -> new ChartSpec.Series(s.name(), s.config(), s.engine(), s.color(),
                s.style(), s.points(), s.values(), null, s.colors(), s.notes(), null)).collect(Collectors.toList());
        exporter.write(spec);
        exporter.write(new ChartSpec(spec.id(), "bare", spec.setting(), spec.title(), spec.kind(), false, spec.x(), spec.y(),
                spec.categories(), bare, List.of(), null, false));
        return paths(dir.resolve("charts/" + spec.stem() + ".svg")) - paths(dir.resolve("charts/bare.svg"));
    }

    static long paths(Path svg) throws Exception {
        return Files.readString(svg).split("<path", -1).length - 1;
    }
}
