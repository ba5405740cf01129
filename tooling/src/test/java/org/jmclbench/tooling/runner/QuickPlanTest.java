package org.jmclbench.tooling.runner;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.stream.Collectors;

import org.jmclbench.tooling.Fixtures;
import org.jmclbench.tooling.runtime.RuntimeDiscovery;
import org.jmclbench.tooling.store.MachineInfo;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** quick's grid: both engines on every JVM, native once per setting, sped up only when it would not fit. */
class QuickPlanTest {

    @TempDir
    Path dir;

    /** The help named the javase and scj engines only, while quick also runs both RTSJ designs. */
    @Test
    void theHelpNamesEveryEngineAndTheRtsjRunsCount() {
        Fixtures.CliResult r = Fixtures.cli("quick", "--help");
        assertEquals(0, r.exitCode(), r.err());
        String help = String.join(" ", r.out().split("\\s+"));
        for (String engine : QuickCommand.ENGINES) {
            assertTrue(help.contains(engine), "quick --help names the engine " + engine + ": " + help);
        }
        for (String engine : QuickCommand.RTSJ_ENGINES) {
            assertTrue(help.contains(engine), "quick --help names the engine " + engine + ": " + help);
        }
        int heavier = QuickCommand.PARTICLES.get(QuickCommand.PARTICLES.size() - 1);
        assertTrue(help.contains("terminate at " + heavier + " particles"), help);
    }

    @Test
    void everyJvmRunsBothEnginesAndNativeOncePerSetting() throws Exception {
        Fixtures.home(dir);
        Files.createDirectories(dir.resolve("data/" + QuickCommand.DATASET));
        for (Path f : Files.list(dir.resolve("data/tiny")).toList()) {
            Files.copy(f, dir.resolve("data/" + QuickCommand.DATASET).resolve(f.getFileName()));
        }
        Path a = Fixtures.fakeJava(dir, "a", "ok", 0, null, 17);
        Path b = Fixtures.fakeJava(dir, "b", "ok", 0, null, 21);
        Path nat = Fixtures.fakeJava(dir, "nat", "ok", 0, null, 21);
        MatrixSpec spec = QuickCommand.spec(dir.resolve("results.db").toString());
        MatrixOptions.apply(spec, "native", nat.toString(), "--native");
        RuntimeDiscovery d = RuntimeDiscovery.discover(List.of(), null);
        d.addJava(a.toString());
        d.addJava(b.toString());
        ResolvedMatrix m = MatrixPlanner.resolve(spec, () -> d, dir, MachineInfo.current());
        Map<String, Long> perRuntimeEngine = m.plan().stream()
                .collect(Collectors.groupingBy(r -> r.runtime().name() + " " + r.engine(), Collectors.counting()));
        assertEquals(Map.of("fake-17 javase", 4L, "fake-17 scj", 4L, "fake-21 javase", 4L, "fake-21 scj", 4L, "native native", 4L),
                perRuntimeEngine, "2 policies x 2 particle counts each");
        assertEquals("fake-21", QuickCommand.newestJvm(d).orElseThrow(), "the RTSJ designs run on the newest JVM");
        MatrixSpec rtsj = QuickCommand.rtsjSpec(dir.resolve("results.db").toString(), "fake-21");
        List<String> cells = MatrixPlanner.resolve(rtsj, () -> d, dir, MachineInfo.current()).plan().stream()
                .map(r -> r.runtime().name() + " " + r.engine() + " " + r.policy() + " " + r.particles()).sorted().toList();
        assertEquals(List.of("fake-21 rtsj terminate 1600", "fake-21 rtsj-atomic terminate 1600"), cells);
    }

    @Test
    void moreJvmsReplayFasterToFitTheBudget() {
        ByteArrayOutputStream text = new ByteArrayOutputStream();
        PrintStream out = new PrintStream(text, true, StandardCharsets.UTF_8);
        assertEquals(1.0, QuickCommand.fitScale(1, true, false, 10.0, out), "one JVM and native replay in real time");
        assertTrue(text.toString(StandardCharsets.UTF_8).startsWith("quick: 14 runs (1 JVM x 2 engines x 4 settings + native + rtsj) of 10 s: about 180 s"),
                text.toString(StandardCharsets.UTF_8));
        double two = QuickCommand.fitScale(2, true, false, 10.0, out);
        assertEquals(0.8, two, 1e-9, "a fresh machine, 2 JVMs, the RTSJ designs and native: 22 runs, 20% faster than real time");
        assertTrue(text.toString(StandardCharsets.UTF_8).contains("quick: 22 runs of 10 s would take about 292 s; replaying at --time-scale 0.80"),
                text.toString(StandardCharsets.UTF_8));
        double four = QuickCommand.fitScale(4, true, false, 10.0, out);
        assertTrue(four < 1.0 && four >= 0.25, "four JVMs are sped up: " + four);
        int runs = 4 * 2 * 4 + 2 + 4;
        assertTrue(runs * 10.0 * four + (4 * 2 * 4 + 2) * QuickCommand.JVM_OVERHEAD_S + 4 * QuickCommand.NATIVE_OVERHEAD_S
                <= QuickCommand.BUDGET_S, "and then fit the budget");
        assertEquals(0.25, QuickCommand.fitScale(40, true, false, 10.0, out), 1e-9, "never faster than 4x");
    }
}
