package org.jmclbench.tooling.runner;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.sql.Connection;
import java.sql.DriverManager;
import java.sql.ResultSet;
import java.sql.Statement;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

import org.jmclbench.tooling.Fixtures;
import org.jmclbench.tooling.cli.CodeVersion;
import org.jmclbench.tooling.load.LoadScenario;
import org.jmclbench.tooling.load.LoadSettings;
import org.jmclbench.tooling.runtime.HvmRuntime;
import org.jmclbench.tooling.runtime.Profile;
import org.jmclbench.tooling.runtime.RuntimeDiscovery;
import org.jmclbench.tooling.runtime.RuntimeInfo;
import org.jmclbench.tooling.runtime.RuntimeKind;
import org.jmclbench.tooling.store.MachineInfo;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

/**
 * The engine and memory-style dimensions of the matrix: planned per JVM (native once), passed to the
 * workload, recorded with each run and its memory areas; a style an engine lacks is unsupported.
 */
class EngineMatrixTest extends FakeJvmHome {
    Path nat;

    @BeforeEach
    void setUpNative() throws Exception {
        nat = Fixtures.fakeJava(dir, "nat", "ok", 0, null, 21);
    }

    private ResolvedMatrix plan(String... kv) {
        MatrixSpec spec = new MatrixSpec();
        for (int i = 0; i < kv.length; i += 2) {
            MatrixOptions.apply(spec, kv[i], kv[i + 1], "--" + kv[i]);
        }
        return MatrixPlanner.resolve(spec, () -> RuntimeDiscovery.discover(List.of(), null), dir, MachineInfo.current());
    }

    @Test
    void enginesMultiplyJvmRunsAndNativeRunsOncePerCell() {
        ResolvedMatrix m = plan("java", fake.toString(), "native", nat.toString(), "runtimes", "native",
                "engines", "javase,scj", "memory", "preallocated,allocating,scoped", "particles", "100,400", "datasets", "tiny");
        List<String> jvm = m.plan().stream().filter(r -> r.runtime().isJvm()).map(r -> r.engine() + " " + r.memory()).toList();
        List<String> nativeRuns = m.plan().stream().filter(r -> !r.runtime().isJvm()).map(r -> r.engine() + " " + r.memory()).toList();
        assertEquals(2 * 3 * 2, jvm.size(), jvm.toString());
        assertEquals(3 * 2, nativeRuns.size(), "one native run per memory style and particle count: " + nativeRuns);
        assertTrue(nativeRuns.stream().allMatch(s -> s.startsWith("native ")), nativeRuns.toString());
        assertEquals(m.plan().size(), m.plan().stream().map(PlannedRun::runKey).distinct().count(), "every run its own key");
    }

    /** An engine registered with the workload (one class, one registration) is one the matrix takes, as it is named. */
    @Test
    void anEngineOfTheWorkloadsRegistryIsAMatrixEngine() {
        ResolvedMatrix m = plan("java", fake.toString(), "engines", RegisteredProbeEngine.NAME + ",rtsj-atomic", "datasets", "tiny");
        assertEquals(List.of(RegisteredProbeEngine.NAME, Engines.RTSJ_ATOMIC), m.plan().stream().map(PlannedRun::engine).sorted().toList());
        assertEquals(List.of("--engine", RegisteredProbeEngine.NAME), Engines.workloadArgs(RegisteredProbeEngine.NAME));
        assertEquals("-" + RegisteredProbeEngine.NAME, Engines.runtimeSuffix(RegisteredProbeEngine.NAME));
        assertTrue(Engines.ALL.containsAll(List.of(RegisteredProbeEngine.NAME, Engines.NATIVE, "hvm")), Engines.ALL.toString());
    }

    @Test
    void theDefaultEngineAndStyleKeepTheKeysOfAStoreMadeBeforeThem() {
        ResolvedMatrix m = plan("java", fake.toString(), "datasets", "tiny");
        PlannedRun r = m.plan().get(0);
        // the run key text of the store's first version, without the engine and memory dimensions
        String before = String.join("\n", "jmclbench-run-key/1", "machine=" + MachineInfo.current().machineId(),
                "runtime=" + r.runtime().name(), "runtimeVersion=" + r.runtime().version(), "profile=default", "policy=skip",
                "particles=400", "dataset=tiny@" + r.dataset().digest(), "load=none", "repetition=1", "seed=1",
                "timeScale=1.0", "workloadArgs=");
        assertEquals(MachineInfo.sha256Hex(before).substring(0, 20), r.runKey());
        RuntimeInfo rt = r.runtime();
        Profile p = r.profile();
        String scj = MatrixPlanner.runKey(MachineInfo.current(), rt, p, Engines.SCJ, Engines.PREALLOCATED, "skip", 400,
                r.dataset(), LoadScenario.NONE, LoadSettings.defaults(), 1, 1, 1.0, List.of());
        String scoped = MatrixPlanner.runKey(MachineInfo.current(), rt, p, Engines.SCJ, "scoped", "skip", 400,
                r.dataset(), LoadScenario.NONE, LoadSettings.defaults(), 1, 1, 1.0, List.of());
        assertNotEquals(r.runKey(), scj);
        assertNotEquals(scj, scoped);
    }

    @Test
    void anUnknownEngineOrMemoryStyleIsBadUsage() throws Exception {
        Fixtures.CliResult r = Fixtures.cli("matrix", "--java", fake.toString(), "--engines", "javase,jamaica",
                "--datasets", "tiny", "--db", db.toString());
        assertEquals(2, r.exitCode(), r.out() + r.err());
        // the tests' class path registers one more engine with the workload
        assertEquals("jmclbench: --engines: unknown engine 'jamaica' (known: javase, scj, rtsj, rtsj-atomic, "
                + RegisteredProbeEngine.NAME + ")", r.err().strip());
        assertFalse(Files.exists(db));

        r = Fixtures.cli("matrix", "--java", fake.toString(), "--memory", "immortal", "--datasets", "tiny", "--db", db.toString());
        assertEquals(2, r.exitCode());
        assertEquals("jmclbench: --memory: unknown memory style 'immortal' (known: preallocated, allocating, scoped)",
                r.err().strip());

        Path file = dir.resolve("m.properties");
        Files.writeString(file, "datasets = tiny\nengines = javase, hvm2\n");
        r = Fixtures.cli("matrix", "--java", fake.toString(), "--matrix", file.toString(), "--db", db.toString());
        assertEquals(2, r.exitCode());
        assertTrue(r.err().startsWith("jmclbench: " + file + ":2: engines: unknown engine 'hvm2'"), r.err());

        r = Fixtures.cli("matrix", "--java", fake.toString(), "--workload-arg", "--engine=scj", "--datasets", "tiny",
                "--db", db.toString());
        assertEquals(2, r.exitCode());
        assertTrue(r.err().contains("'--engine=scj' is set by the runner"), r.err());
    }

    @Test
    void aMatrixFileNamesTheEngines() throws Exception {
        Path file = dir.resolve("m.properties");
        Files.writeString(file, "datasets = tiny\nengines = javase, scj\nmemory = preallocated, scoped\n");
        Fixtures.CliResult r = Fixtures.cli("matrix", "--java", fake.toString(), "--matrix", file.toString(), "--dry-run",
                "--db", db.toString());
        assertEquals(0, r.exitCode(), r.err());
        assertTrue(r.out().startsWith("4 runs planned"), r.out());
        assertTrue(r.out().contains("fake-21 default scj scoped skip 400p tiny #1"), r.out());
        assertTrue(r.out().contains("fake-21 default skip 400p tiny #1"), r.out());
    }

    /** One row of {@code runs} as the test reads it. */
    private record Row(String engine, String memory, String status, String failure, String command) {
    }

    @Test
    void theMemoryModelExperimentIsOneMatrix() throws Exception {
        Fixtures.CliResult r = Fixtures.cli("matrix", "--java", fake.toString(), "--runtimes", "native", "--native", nat.toString(),
                "--engines", "javase,scj", "--memory", "preallocated,allocating,scoped", "--particles", "100",
                "--datasets", "tiny", "--db", db.toString());
        assertEquals(0, r.exitCode(), r.out() + r.err());
        Map<String, Row> rows = new HashMap<>();
        Map<String, List<String>> areas = new HashMap<>();
        try (Connection c = DriverManager.getConnection("jdbc:sqlite:" + db); Statement s = c.createStatement()) {
            try (ResultSet rs = s.executeQuery("SELECT runtime, engine, memory, status, failure, command_json, run_key FROM runs")) {
                while (rs.next()) {
                    String id = rs.getString(1) + " " + rs.getString(2) + " " + rs.getString(3);
                    rows.put(id, new Row(rs.getString(2), rs.getString(3), rs.getString(4), rs.getString(5), rs.getString(6)));
                    areas.put(id, new ArrayList<>());
                }
            }
            try (ResultSet rs = s.executeQuery("SELECT r.runtime, r.engine, r.memory, a.name, a.size, a.peak_bytes, a.bytes_per_release"
                    + " FROM memory_areas a JOIN runs r USING (run_key) ORDER BY a.rowid")) {
                while (rs.next()) {
                    areas.get(rs.getString(1) + " " + rs.getString(2) + " " + rs.getString(3))
                            .add(rs.getString(4) + "=" + rs.getLong(6) + (rs.getObject(7) == null ? "" : "/" + rs.getLong(7)));
                }
            }
            try (ResultSet rs = s.executeQuery("PRAGMA user_version")) {
                assertEquals(3, rs.getInt(1));
            }
            try (ResultSet rs = s.executeQuery("SELECT DISTINCT code_version FROM runs")) {
                assertTrue(rs.next());
                assertEquals(CodeVersion.current(), rs.getString(1), "every run carries the commit that made it");
                assertFalse(rs.next());
            }
        }
        assertEquals(9, rows.size(), rows.keySet().toString()); // fake-21: 2 engines x 3 styles; native: 3 styles
        for (String ok : List.of("fake-21 javase preallocated", "fake-21 javase allocating", "fake-21 scj preallocated",
                "fake-21 scj scoped", "native native preallocated", "native native allocating")) {
            assertEquals("ok", rows.get(ok).status(), ok + ": " + rows.get(ok));
        }
        assertEquals("unsupported", rows.get("fake-21 javase scoped").status());
        assertEquals("engine javase has no memory style 'scoped' (it has preallocated, allocating)", rows.get("fake-21 javase scoped").failure());
        assertEquals("unsupported", rows.get("fake-21 scj allocating").status());
        assertEquals("unsupported", rows.get("native native scoped").status());
        assertEquals("[]", rows.get("fake-21 scj allocating").command(), "nothing ran");

        String scj = rows.get("fake-21 scj scoped").command();
        assertTrue(scj.contains("\"--engine\",\"scj\"") && scj.contains("\"--memory\",\"scoped\"") && scj.contains("\"-j\",\"fake-21-scj\""), scj);
        String javase = rows.get("fake-21 javase preallocated").command();
        assertFalse(javase.contains("--engine") || javase.contains("--memory"), javase);
        assertFalse(rows.get("native native allocating").command().contains("--engine"));

        assertEquals(List.of("immortal=100000", "mission=15000", "predict=4000/4000", "update=8000/8000"),
                areas.get("fake-21 scj scoped"), "private memory: the peak of one release");
        assertEquals(List.of("immortal=100000", "mission=15000", "predict=0/0", "update=0/0"), areas.get("fake-21 scj preallocated"));
        assertEquals(List.of("heap=2100000"), areas.get("fake-21 javase preallocated"));
        assertEquals(List.of(), areas.get("native native preallocated"), "C reports no areas");

        // rerunning resumes: every run, unsupported ones too, is already there
        r = Fixtures.cli("matrix", "--java", fake.toString(), "--runtimes", "native", "--native", nat.toString(),
                "--engines", "javase,scj", "--memory", "preallocated,allocating,scoped", "--particles", "100",
                "--datasets", "tiny", "--db", db.toString());
        assertTrue(r.out().contains("9 runs, 9 already in"), r.out());
    }

    @Test
    void aRunWhoseSummaryNamesAnotherEngineIsGarbage() {
        com.fasterxml.jackson.databind.ObjectMapper json = new com.fasterxml.jackson.databind.ObjectMapper();
        ResolvedMatrix m = plan("java", fake.toString(), "engines", "scj", "memory", "scoped", "datasets", "tiny");
        PlannedRun run = m.plan().get(0);
        String base = "{\"parameters\": {\"particles\": 400, \"ideal\": false, \"policy\": \"skip\", \"seed\": 1%s}%s}";
        assertEquals("engine missing, asked scj", MatrixRunner.describesAnotherRun(read(json, base, "", ""), run),
                "a workload that knows no engines ran the Java SE engine");
        assertEquals("engine javase, asked scj", MatrixRunner.describesAnotherRun(
                read(json, base, ", \"engine\": \"javase\"", ""), run));
        assertEquals("memory preallocated, asked scoped", MatrixRunner.describesAnotherRun(
                read(json, base, ", \"engine\": \"scj\", \"memory\": \"preallocated\"", ""), run));
        assertNull(MatrixRunner.describesAnotherRun(read(json, base, ", \"memory\": \"scoped\"", ", \"engine\": {\"kind\": \"scj\"}"), run),
                "engine.kind stands in for parameters.engine");
    }

    @Test
    void anHvmRunIsGarbageUnlessItsExecutableRanInTheProfilesMode() {
        com.fasterxml.jackson.databind.ObjectMapper json = new com.fasterxml.jackson.databind.ObjectMapper();
        RuntimeInfo hvm = new RuntimeInfo("hvm",
                RuntimeKind.HVM, "icecap", "1", 0, Path.of("/j"), Path.of("/j"));
        String base = "{\"parameters\": {\"particles\": 400, \"ideal\": false, \"policy\": \"skip\", \"seed\": 1,"
                + " \"engine\": \"hvm\"}, \"engine\": {\"kind\": \"hvm\"%s}%s}";
        for (String profile : List.of("default", "int")) {
            Profile p = Profile.parse(profile, "t")
                    .effectiveFor(RuntimeKind.HVM);
            PlannedRun run = new PlannedRun(hvm, p, "hvm", "preallocated", "skip", 400,
                    new Dataset("tiny", Path.of("/d"), 10, "x"), 1, 1, LoadScenario.NONE, "k");
            String asked = profile.equals("int") ? "interpreted" : "compiled";
            String other = profile.equals("int") ? "compiled" : "interpreted";
            assertNull(MatrixRunner.describesAnotherRun(read(json, base, ", \"mode\": \"" + asked + "\"", ""), run));
            assertEquals("hvm mode " + other + ", asked " + asked,
                    MatrixRunner.describesAnotherRun(read(json, base, ", \"mode\": \"" + other + "\"", ""), run));
            assertEquals("hvm mode missing, asked " + asked, MatrixRunner.describesAnotherRun(read(json, base, "", ""), run));
            assertEquals(Map.of("JMCLBENCH_HVM_MODE", asked),
                    HvmRuntime.environment(p), "what the executable is built in");
        }
    }

    private static com.fasterxml.jackson.databind.JsonNode read(com.fasterxml.jackson.databind.ObjectMapper json, String format,
                                                                 String params, String top) {
        try {
            return json.readTree(String.format(format, params, top));
        } catch (java.io.IOException e) {
            throw new AssertionError(e);
        }
    }
}
