package org.jmclbench.verification;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.net.URISyntaxException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.List;
import java.util.Map;

import org.jmclbench.core.mcl.AbortSignal;
import org.jmclbench.core.mcl.MotionModel;
import org.jmclbench.rtsjcompat.Atc;
import org.jmclbench.verification.bytecode.AbortBound;
import org.jmclbench.verification.bytecode.AbortPollCheck;
import org.jmclbench.verification.bytecode.ClassPool;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.objectweb.asm.tree.ClassNode;
import org.objectweb.asm.tree.MethodNode;

/**
 * The abort-bound analysis on seeded jobs whose bounds are known: polls every 16 then 32 steps
 * (32), a loop without a poll (whole loop, named), an RTSJ job whose signal delivers (64) and the
 * same job deferred in a synchronized block (the whole job, the block named).
 */
class AbortBoundTest {
    private static final String SEEDED = "org/jmclbench/verification/seeded/bound/";
    private static ClassPool pool;

    @BeforeAll
    static void load() throws Exception {
        pool = ClassPool.of(List.of(Paths.get("target", "test-classes"), codeOf(AbortSignal.class), codeOf(Atc.class)));
    }

    private static Path codeOf(Class<?> c) throws URISyntaxException {
        return Paths.get(c.getProtectionDomain().getCodeSource().getLocation().toURI());
    }

    private static ClassPool.Owned method(String cls, String name) {
        ClassNode c = pool.get(SEEDED + cls);
        for (MethodNode m : c.methods) {
            if (m.name.equals(name)) {
                return new ClassPool.Owned(c, m);
            }
        }
        throw new AssertionError(cls + "." + name);
    }

    private static AbortBound bound(AbortBound.Mode mode, String design) {
        return new AbortBound(pool, n -> n.startsWith("org/jmclbench/") && !n.startsWith("org/jmclbench/rtsjcompat/"), 64, mode,
                Map.of(SEEDED + "AtcJob$Design", design));
    }

    @Test
    void theLongestGapIsTheWidestPollStride() {
        AbortBound.Result r = bound(AbortBound.Mode.COOPERATIVE, "DELIVERED").analyse(List.of(method("BoundJob", "run")));
        assertEquals(2, r.loops().size());
        assertEquals(32, r.longestSteps());
        assertEquals(r.loops().get(1), r.longest(), "the second loop");
        assertTrue(r.longestBytecodes() >= 32 * 8, "a step is at least a handful of bytecodes: " + r.longestBytecodes());
        assertTrue(r.deferrals().isEmpty(), r.deferrals().toString());
        assertFalse(r.wholeJob());
    }

    @Test
    void aLoopWithoutAPollRunsWholeAndIsNamed() {
        AbortBound.Result r = bound(AbortBound.Mode.COOPERATIVE, "DELIVERED").analyse(List.of(method("BoundJob", "unpolledTail")));
        assertEquals(AbortPollCheck.UNKNOWN, r.longestSteps());
        assertFalse(r.wholeJob(), "the first loop polls");
        int line = r.longest().line();
        assertEquals(List.of("org.jmclbench.verification.seeded.bound.BoundJob.unpolledTail:" + line
                + ": particle loop with no abort point (runs whole after a request)"), r.deferrals());
    }

    @Test
    void anAtcJobWhoseSignalDeliversIsBoundByItsStride() {
        AbortBound.Result r = bound(AbortBound.Mode.ATC, "DELIVERED").analyse(List.of(method("AtcJob", "run")));
        assertEquals(List.of(SEEDED + "AtcJob$Points"), r.signals(), "the design's branch only");
        assertTrue(r.signalDelivers());
        assertEquals(64, r.longestSteps());
        assertTrue(r.deferrals().isEmpty(), "the synchronized branch is the other design's: " + r.deferrals());
    }

    @Test
    void theDeferredDesignIsTheWholeJobAndItsMonitorIsNamed() {
        AbortBound.Result r = bound(AbortBound.Mode.ATC, "DEFERRED").analyse(List.of(method("AtcJob", "run")));
        assertEquals(List.of("org/jmclbench/core/mcl/AbortSignal$1"), r.signals(), "AbortSignal.NEVER's class");
        assertFalse(r.signalDelivers());
        assertTrue(r.wholeJob());
        assertTrue(r.deferrals().get(0).startsWith("org.jmclbench.verification.seeded.bound.AtcJob.job:"), r.deferrals().toString());
        assertTrue(r.deferrals().get(0).contains("synchronized block"), r.deferrals().get(0));
        assertTrue(r.deferrals().get(1).startsWith("non-AI code"), r.deferrals().toString());
    }

    @Test
    void verifyRecordsEachShippedEnginesBoundForTheReport() throws Exception {
        // as verify builds it: the shipped classes and verification's own, whose subclasses of the robot no run executes
        ClassPool shipped = ClassPool.of(List.of(Paths.get("target", "classes"),
                codeOf(Class.forName("org.jmclbench.workload.rtsj.RtsjReplay")), codeOf(Class.forName("org.jmclbench.scj.Robot")),
                codeOf(AbortSignal.class), codeOf(Atc.class)));
        Map<String, Map<String, Object>> preallocated = new java.util.TreeMap<>();
        for (Map<String, Object> b : AbortBoundMain.allBounds(shipped)) {
            if (b.get("memory").equals("preallocated")) {
                preallocated.put((String) b.get("engine"), b);
            }
        }
        assertEquals(List.of("hvm", "javase", "rtsj", "rtsj-atomic", "scj"), List.copyOf(preallocated.keySet()));
        for (String polling : List.of("javase", "scj", "hvm", "rtsj-atomic")) {
            assertEquals((long) MotionModel.ABORT_BLOCK, preallocated.get(polling).get("steps"), polling);
        }
        Map<String, Object> thesis = preallocated.get("rtsj");
        assertEquals(null, thesis.get("steps"), "the thesis design defers the AIE for the whole job");
        assertEquals(true, thesis.get("wholeJob"));
        assertTrue(thesis.get("deferrals").toString().contains("synchronized"), thesis.get("deferrals").toString());
    }

    @Test
    void withARunTheOptionsLeftOutAreTheRunsAndAContradictionIsBadInput(@TempDir Path run) throws Exception {
        Files.writeString(run.resolve("summary.json"), "{\"parameters\": {\"engine\": \"rtsj\", \"rtsjDesign\": \"atomic\","
                + " \"memory\": \"preallocated\", \"particles\": 1600}, \"tasks\": {\"update\": {\"taskLatencyNs\":"
                + " {\"p50\": 320000, \"max\": 640000}}, \"all\": {\"abortLatencyNs\": {\"count\": 0}}}}");
        String shipped = Paths.get("target", "classes") + ":" + codeOf(Class.forName("org.jmclbench.workload.rtsj.RtsjReplay"))
                + ":" + codeOf(AbortSignal.class) + ":" + codeOf(Atc.class);
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        PrintStream o = new PrintStream(out, true, StandardCharsets.UTF_8);
        PrintStream e = new PrintStream(err, true, StandardCharsets.UTF_8);
        assertEquals(0, AbortBoundMain.run(new String[] {"--classes", shipped, "--run", run.toString()}, o, e), err.toString());
        String report = out.toString(StandardCharsets.UTF_8);
        assertTrue(report.startsWith("abort-bound: rtsj atomic, memory preallocated"), report);
        // 64 steps of a particle step from the max: 640000 ns / 1600 particles
        assertTrue(report.contains("bound on abort latency: 64 steps x step = 0.013 ms (from the max: 0.026 ms)"), report);
        assertEquals(2, AbortBoundMain.run(new String[] {"--rtsj-design", "thesis", "--classes", shipped, "--run", run.toString()}, o, e));
        assertEquals("jmclbench: abort-bound: --rtsj-design: 'thesis', but the run in " + run + " used 'atomic'",
                err.toString(StandardCharsets.UTF_8).strip());
    }

    @Test
    void aRunWhoseSummaryIsNotJsonIsOneLineNamingItsLine(@TempDir Path run) throws Exception {
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        PrintStream e = new PrintStream(err, true, StandardCharsets.UTF_8);
        PrintStream o = new PrintStream(new ByteArrayOutputStream(), true, StandardCharsets.UTF_8);
        Path summary = run.resolve("summary.json");
        Files.writeString(summary, "{\"parameters\":\n");
        assertEquals(2, AbortBoundMain.run(new String[] {"--classes", "x", "--run", run.toString()}, o, e));
        Files.writeString(summary, "[1, 2]\n");
        assertEquals(2, AbortBoundMain.run(new String[] {"--classes", "x", "--run", run.toString()}, o, e));
        String[] lines = err.toString(StandardCharsets.UTF_8).split("\n");
        assertEquals(2, lines.length, err.toString(StandardCharsets.UTF_8));
        assertTrue(lines[0].startsWith("jmclbench: abort-bound: --run: " + summary + ":2: not JSON ("), lines[0]);
        // not "--engine: required": the file is what is wrong
        assertEquals("jmclbench: abort-bound: --run: " + summary + ": not a run's summary.json (no JSON object)", lines[1]);
    }

    /** A runaway summary.json (3 GB, sparse) is refused by its size, not read whole into memory. */
    @Test
    void aRunawaySummaryIsOneLineNotReadWhole(@TempDir Path run) throws Exception {
        Path summary = run.resolve("summary.json");
        try (java.io.RandomAccessFile f = new java.io.RandomAccessFile(summary.toFile(), "rw")) {
            f.setLength(3L << 30);
        }
        assertEquals("jmclbench: abort-bound: --run: " + summary + ": not a run's summary.json (3221225472 bytes, more than 16777216)",
                refusal("--classes", "x", "--run", run.toString()));
    }

    /** What abort-bound says on stderr when it refuses {@code args} (exit 2). */
    private static String refusal(String... args) {
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        PrintStream o = new PrintStream(new ByteArrayOutputStream(), true, StandardCharsets.UTF_8);
        assertEquals(2, AbortBoundMain.run(args, o, new PrintStream(err, true, StandardCharsets.UTF_8)));
        return err.toString(StandardCharsets.UTF_8).strip();
    }

    /** A bound for a job no run has would stand beside no measurement: the workload's own refusal, one line. */
    @Test
    void anEngineMemoryStyleOrDesignNoRunHasIsRefusedAsTheWorkloadRefusesIt() {
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        PrintStream e = new PrintStream(err, true, StandardCharsets.UTF_8);
        PrintStream o = new PrintStream(new ByteArrayOutputStream(), true, StandardCharsets.UTF_8);
        assertEquals(2, AbortBoundMain.run(new String[] {"--engine", "rtsj", "--memory", "scoped", "--classes", "x"}, o, e));
        assertEquals(2, AbortBoundMain.run(new String[] {"--engine", "javase", "--rtsj-design", "atomic", "--classes", "x"}, o, e));
        assertEquals(2, AbortBoundMain.run(new String[] {"--engine", "hvm", "--memory", "allocating", "--classes", "x"}, o, e));
        String[] lines = err.toString(StandardCharsets.UTF_8).split("\n");
        assertEquals(3, lines.length, err.toString(StandardCharsets.UTF_8));
        assertTrue(lines[0].startsWith("jmclbench: abort-bound: --memory: 'scoped' is not a memory style of the rtsj engine"), lines[0]);
        assertEquals("jmclbench: abort-bound: --rtsj-design: chooses the rtsj engine's design: needs --engine rtsj", lines[1]);
        assertTrue(lines[2].startsWith("jmclbench: abort-bound: --memory: 'allocating' is not a memory style of the SCJ mission the hvm runs"),
                lines[2]);
    }

    @Test
    void badInputIsOneLineAndExitTwo() {
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        PrintStream e = new PrintStream(err, true, StandardCharsets.UTF_8);
        PrintStream o = new PrintStream(new ByteArrayOutputStream(), true, StandardCharsets.UTF_8);
        assertEquals(2, AbortBoundMain.run(new String[] {"--engine", "native", "--classes", "x"}, o, e));
        assertEquals(2, AbortBoundMain.run(new String[] {"--engine", "rtsj", "--rtsj-design", "fast", "--classes", "x"}, o, e));
        assertEquals(2, AbortBoundMain.run(new String[] {"--engine", "javase", "--classes", "/no/such.jar"}, o, e));
        assertEquals(2, AbortBoundMain.run(new String[] {"--engine", "javase", "--bogus"}, o, e));
        String[] lines = err.toString(StandardCharsets.UTF_8).split("\n");
        assertEquals(4, lines.length);
        assertTrue(lines[0].startsWith("jmclbench: abort-bound: --engine: 'native' is not one of"), lines[0]);
        assertTrue(lines[1].startsWith("jmclbench: abort-bound: --rtsj-design: 'fast'"), lines[1]);
        assertTrue(lines[2].startsWith("jmclbench: abort-bound: --classes: no such file or folder"), lines[2]);
        assertEquals("jmclbench: abort-bound: Unknown option: '--bogus'", lines[3]);
    }
}
