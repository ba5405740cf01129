package org.jmclbench.tooling.report;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.stream.Collectors;

import org.jmclbench.tooling.cli.JmclbenchCli;
import org.jmclbench.tooling.store.StoredRuns;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Engines and memory areas in the report and compare: engine-by-runtime rows, the memory areas
 * of each configuration, the exported memory chart, and a store made before engines.
 */
class EngineReportTest {

    @TempDir
    Path dir;

    private ReportModel model(Path db) throws Exception {
        try (StoredRuns store = StoredRuns.open(db, "--db")) {
            return ReportModel.build(store, line -> { });
        }
    }

    private static ReportModel.Cell cell(ReportModel m, String config, int particles) {
        return m.cells.stream().filter(c -> c.config.equals(config) && c.particles == particles).findFirst()
                .orElseThrow(() -> new AssertionError("no cell " + config + " " + particles + " in "
                        + m.cells.stream().map(c -> c.config).distinct().toList()));
    }

    @Test
    void anHvmRowSaysWhetherTheMissionRanCompiledOrInterpreted() throws Exception {
        com.fasterxml.jackson.databind.ObjectMapper json = new com.fasterxml.jackson.databind.ObjectMapper();
        assertTrue(ConfigurationFacts.facts(json.readTree("{\"engine\": {\"kind\": \"hvm\", \"level\": 1, \"mode\": \"compiled\"}}"))
                .contains("engine hvm (SCJ level 1, compiled)"));
        assertTrue(ConfigurationFacts.facts(json.readTree("{\"engine\": {\"kind\": \"hvm\", \"level\": 1, \"mode\": \"interpreted\"}}"))
                .contains("engine hvm (SCJ level 1, interpreted)"));
        assertTrue(ConfigurationFacts.facts(json.readTree("{\"engine\": {\"kind\": \"scj\", \"level\": 1}}"))
                .contains("engine scj (SCJ level 1)"), "no mode, none said");
    }

    @Test
    void eachEngineAndMemoryStyleIsARowWithItsAreas() throws Exception {
        Path db = ReportFixtures.write(ReportFixtures.engines(), dir, "results.db");
        ReportModel m = model(db);
        assertEquals(List.of("javase", "native", "scj"), m.engines);
        assertEquals(List.of(ReportFixtures.NATIVE, ReportFixtures.JAVASE_ALLOCATING, ReportFixtures.JAVASE,
                ReportFixtures.SCJ, ReportFixtures.SCJ_SCOPED), m.configs.stream().map(ReportModel.ConfigInfo::id).toList());
        ReportModel.ConfigInfo scj = m.configs.stream().filter(c -> c.id().equals(ReportFixtures.SCJ_SCOPED)).findFirst().get();
        assertEquals("scj", scj.engine());
        assertEquals("scoped", scj.memory());

        Map<String, ReportModel.MemoryArea> scoped = cell(m, ReportFixtures.SCJ_SCOPED, 400).memoryAreas.stream()
                .collect(Collectors.toMap(ReportModel.MemoryArea::name, a -> a));
        assertEquals(List.of("immortal", "mission", "predict", "update"),
                cell(m, ReportFixtures.SCJ_SCOPED, 400).memoryAreas.stream().map(ReportModel.MemoryArea::name).toList());
        assertEquals(400L * 80, scoped.get("update").peakBytes(), "a private area: one release's peak");
        assertEquals(400.0 * 80, scoped.get("update").bytesPerRelease());
        assertEquals(256L << 10, scoped.get("update").size());
        assertEquals(2, scoped.get("update").runs(), "both repetitions");
        assertEquals(0L, cell(m, ReportFixtures.SCJ, 400).memoryAreas.get(2).peakBytes(), "preallocated: releases allocate nothing");
        assertEquals(List.of("heap"), cell(m, ReportFixtures.JAVASE, 100).memoryAreas.stream().map(ReportModel.MemoryArea::name).toList());
        assertTrue(cell(m, ReportFixtures.NATIVE, 100).memoryAreas.isEmpty());
        assertEquals("native", cell(m, ReportFixtures.NATIVE, 100).engine);
    }

    @Test
    void theReleasesThatAllocatedAreSummedOverTheRunsFromTheirSummaries() {
        java.util.List<org.jmclbench.tooling.store.StoredRun> runs = new java.util.ArrayList<>();
        for (int allocating : new int[] {1, 0, 2}) {
            org.jmclbench.tooling.store.StoredRun r = new org.jmclbench.tooling.store.StoredRun();
            r.summaryJson = "{\"memory\": {\"areas\": [{\"name\": \"update\", \"releases\": 90, \"allocatingReleases\": "
                    + allocating + "}, {\"name\": \"mission\", \"releases\": null}]}}";
            runs.add(r);
        }
        assertEquals(270L, CellAggregates.summedAreaField(runs, "update", "releases"));
        assertEquals(3L, CellAggregates.summedAreaField(runs, "update", "allocatingReleases"));
        assertEquals(null, CellAggregates.summedAreaField(runs, "mission", "releases"), "no run told");
    }

    @Test
    void theMemoryChartIsExportedWithEveryArea() throws Exception {
        Path db = ReportFixtures.write(ReportFixtures.engines(), dir, "results.db");
        Path out = dir.resolve("report");
        assertEquals(0, JmclbenchCli.execute("report", "--db", db.toString(), "--out", out.toString()));
        Path svg = out.resolve("charts/match-short-skip-400-memory.svg");
        assertTrue(Files.isRegularFile(out.resolve("charts/match-short-skip-400-memory.png")));
        String text = Files.readString(svg);
        for (String area : List.of("heap", "immortal", "mission", "predict", "update")) {
            assertTrue(text.contains(">" + area + "<"), "legend entry " + area);
        }
        List<String> texts = java.util.regex.Pattern.compile("<text[^>]*>([^<]*)<").matcher(text).results().map(r -> r.group(1)).toList();
        assertTrue(texts.stream().anyMatch(t -> t.contains("scoped")), "the configurations are the categories: " + texts);
    }

    @Test
    void aStoreMadeBeforeEnginesKeepsItsLabels() throws Exception {
        FixtureDb f = ReportFixtures.mixed();
        f.legacySchema = true;
        Path db = ReportFixtures.write(f, dir, "old.db");
        ReportModel m = model(db);
        assertTrue(m.configs.stream().map(ReportModel.ConfigInfo::id).toList().contains("temurin-17/g1"));
        assertEquals(List.of("javase", "native"), m.engines, "JVM runs were the Java SE engine, native its own");
        assertTrue(m.cells.stream().allMatch(c -> c.memoryAreas.isEmpty() && "preallocated".equals(c.memory)));
        Path out = dir.resolve("old-report");
        assertEquals(0, JmclbenchCli.execute("report", "--db", db.toString(), "--out", out.toString(), "--no-export"));
    }

    @Test
    void compareNamesAnEngineAndShowsEngineRows() throws Exception {
        Path db = ReportFixtures.write(ReportFixtures.engines(), dir, "results.db");
        String out = CompareCommandTest.run(0, "compare", "--db", db.toString(), "--a", "temurin-25", "--b", "temurin-25/scj")[0];
        assertTrue(out.startsWith("A: temurin-25\nB: temurin-25/scj\n"), out);
        assertTrue(out.contains("== match-short  skip  400 particles =="), out);
        // the Java SE engine, preallocated, is what a bare runtime name means beside its SCJ runs
        out = CompareCommandTest.run(0, "compare", "--db", db.toString(), "--a", ReportFixtures.JAVASE,
                "--b", "temurin-25/g1/scj/scoped", "--particles", "100")[0];
        assertTrue(out.contains("task latency mean (ms)"), out);
        String err = CompareCommandTest.run(2, "compare", "--db", db.toString(), "--a", "temurin-25/hvm", "--b", "native")[1];
        assertTrue(err.contains("--a: no configuration temurin-25/hvm in "), err); // the runtime is known, its hvm engine is not

        // two stores: each engine-by-runtime configuration is compared with its namesake
        FixtureDb slow = ReportFixtures.engines();
        slow.seed = 2;
        slow.configs = new ArrayList<>(slow.configs.stream().map(c -> new FixtureDb.Config(c.runtime(), c.profile(), c.version(),
                c.speed() * 2, c.status(), c.engine(), c.memory())).toList());
        Path other = ReportFixtures.write(slow, dir, "slow.db");
        out = CompareCommandTest.run(0, "compare", db.toString(), other.toString(), "--particles", "400")[0];
        for (String cfg : List.of(ReportFixtures.JAVASE, ReportFixtures.JAVASE_ALLOCATING, ReportFixtures.SCJ,
                ReportFixtures.SCJ_SCOPED, ReportFixtures.NATIVE)) {
            assertTrue(out.contains("== match-short  skip  400 particles  " + cfg + " =="), cfg + " in\n" + out);
        }
    }
}
