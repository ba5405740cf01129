package org.jmclbench.workload;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;

import org.jmclbench.core.mcl.MclConfig;
import org.jmclbench.core.policy.OverrunPolicy;
import org.junit.jupiter.api.Test;

/** The workload's command line (FORMATS 2): thesis flags, long options, errors naming the option. */
class RunOptionsParserTest {
    @Test
    void defaults() throws BadInputException {
        RunOptions o = RunOptionsParser.parse(new String[] {"run"});
        assertEquals(400, o.particles);
        assertEquals(1, o.number);
        assertEquals("results", o.out);
        assertEquals(OverrunPolicy.SKIP, o.policy);
        assertFalse(o.ideal);
        assertFalse(o.covariance);
        assertEquals(MclConfig.Memory.PREALLOCATED, o.memory);
        assertEquals(MclConfig.Estimate.MEAN, o.estimate);
        assertEquals(MclConfig.Resample.SYSTEMATIC, o.resample);
        assertEquals(MclConfig.Init.KNOWN, o.init);
        assertEquals(1, o.seed);
        assertEquals(1.0, o.timeScale);
        assertNull(o.dataset);
        assertTrue(o.effectiveRuntimeName().matches("[a-z0-9._+-]+"), o.effectiveRuntimeName());
        assertEquals("SkipTest", o.testFolder());
    }

    @Test
    void theEngineDefaultsToJavaSeAndTheScjEnginesRunsGetTheirOwnRuntimeName() throws BadInputException {
        RunOptions se = RunOptionsParser.parse(new String[] {"run"});
        assertEquals("javase", se.engine);
        RunOptions scj = RunOptionsParser.parse(new String[] {"run", "--engine", "scj", "--memory", "scoped",
                "--area-size", "mission=300000", "--area-size=update=4096"});
        assertEquals("scj", scj.engine);
        assertEquals(MclConfig.Memory.SCOPED, scj.memory);
        assertEquals(se.effectiveRuntimeName() + "-scj", scj.effectiveRuntimeName());
        assertEquals(300000L, scj.areaSizes.get("mission"));
        assertEquals(4096L, scj.areaSizes.get("update"));
        assertEquals("mine", RunOptionsParser.parse(new String[] {"--engine", "scj", "-j", "mine"}).effectiveRuntimeName());
    }

    @Test
    void thesisFlags() throws BadInputException {
        RunOptions o = RunOptionsParser.parse(new String[] {"-p", "1000", "-n", "7", "-j", "sun-rts", "-O", "out",
            "-odo", "a.txt", "-laser", "b.txt", "-real", "c.txt", "-T", "-c"});
        assertEquals(1000, o.particles);
        assertEquals(7, o.number);
        assertEquals("sun-rts", o.runtimeName);
        assertEquals("out", o.out);
        assertEquals("a.txt", o.odo);
        assertEquals("b.txt", o.laser);
        assertEquals("c.txt", o.real);
        assertEquals(OverrunPolicy.TERMINATE, o.policy);
        assertEquals("TermTest", o.testFolder());
        assertTrue(o.covariance);
        assertTrue(RunOptionsParser.parse(new String[] {"-h"}).help);
    }

    @Test
    void longOptions() throws BadInputException {
        RunOptions o = RunOptionsParser.parse(new String[] {"run", "--particles=250", "--number", "3",
            "--runtime-name", "temurin-25", "--out", "o", "--dataset", "data/stay", "--policy", "queue",
            "--covariance", "--memory", "allocating", "--estimate", "best", "--resample=multinomial", "--init",
            "uniform", "--seed", "-9", "--time-scale", "0.5", "--warmup", "2.5", "--spin-us", "100", "--gc-log",
            "--force"});
        assertEquals(250, o.particles);
        assertEquals(3, o.number);
        assertEquals("temurin-25", o.effectiveRuntimeName());
        assertEquals("data/stay", o.dataset);
        assertEquals(OverrunPolicy.QUEUE, o.policy);
        assertTrue(o.covariance);
        assertEquals(MclConfig.Memory.ALLOCATING, o.memory);
        assertEquals(MclConfig.Estimate.BEST, o.estimate);
        assertEquals(MclConfig.Resample.MULTINOMIAL, o.resample);
        assertEquals(MclConfig.Init.UNIFORM, o.init);
        assertEquals(-9, o.seed);
        assertEquals(0.5, o.timeScale);
        assertEquals(2.5, o.warmupS);
        assertEquals(100, o.spinUs);
        assertTrue(o.gcLog && o.force && !o.ideal);
        assertEquals("QueueTest", o.testFolder());
        MclConfig c = o.mclConfig();
        assertEquals(250, c.particles);
        assertEquals(-9, c.seed);
        assertTrue(c.covariance);
    }

    @Test
    void anIdealRunRefusesWhatItCannotApply() throws BadInputException {
        // both were accepted and ignored: --spin-us recorded as parameters.spinUs though no release
        // was spun for, --area-size with --engine scj though an ideal run has no SCJ areas
        assertEquals("--spin-us: an ideal run has no releases to spin before (--ideal)",
                error("--ideal", "--spin-us", "100"));
        assertEquals("--spin-us: an ideal run has no releases to spin before (--ideal)",
                error("--engine", "rtsj", "--ideal", "--spin-us", "1"));
        assertEquals("--area-size: an ideal run has no SCJ memory areas (--ideal)",
                error("--engine", "scj", "--ideal", "--area-size", "mission=100000"));
        RunOptions o = RunOptionsParser.parse(new String[] {"--ideal", "--spin-us", "0", "--gc-log", "--warmup", "1"});
        assertTrue(o.ideal && o.spinUs == 0 && o.gcLog);
        assertEquals("IdealTest", RunOptionsParser.parse(new String[] {"--engine", "scj", "--ideal"}).testFolder());
    }

    private static String error(String... args) {
        return assertThrows(BadInputException.class, () -> RunOptionsParser.parse(args)).getMessage();
    }

    /** The usage's --policy line names every policy of OverrunPolicy (it listed three by hand). */
    @Test
    void usageNamesEveryPolicy() {
        String line = java.util.Arrays.stream(RunOptionsParser.USAGE.split("\n")).filter(l -> l.startsWith("  --policy "))
                .findFirst().orElseThrow(AssertionError::new);
        for (OverrunPolicy p : OverrunPolicy.values()) {
            assertTrue(line.contains(p.label), p.label + " in " + line);
        }
    }

    /**
     * Every policy's rule is in OverrunPolicy, which the engines that decide ask (the rtsj replay, the
     * SCJ mission's gate, so also hvm): each runs every policy. The rtsj engine once ran one it lacked
     * as queue; then such a policy was refused.
     */
    @Test
    void everyEngineRunsEveryPolicy() throws BadInputException {
        for (OverrunPolicy p : OverrunPolicy.values()) {
            for (String engine : new String[] {"javase", "rtsj", "scj"}) {
                assertEquals(p, RunOptionsParser.parse(new String[] {"--engine", engine, "--policy", p.label}).policy, engine + " " + p.label);
            }
        }
    }

    @Test
    void errorsNameTheOption() {
        assertEquals("--frobnicate: unknown option (see --help)", error("--frobnicate"));
        assertEquals("-x: unknown option (see --help)", error("-p", "10", "-x"));
        assertEquals("--frob: unknown option (see --help)", error("--frob=1"));
        assertEquals("-p: needs a value", error("-p"));
        assertEquals("-p: not an integer: 'many'", error("-p", "many"));
        assertEquals("-p: 0 is out of range [1, 100000000]", error("-p", "0"));
        // every policy, in code order: a policy added to OverrunPolicy is named without a change here
        assertEquals("--policy: 'later' is not one of " + RunOptionsParser.policyLabels(), error("--policy", "later"));
        assertTrue(RunOptionsParser.policyLabels().startsWith("skip|terminate|queue"), RunOptionsParser.policyLabels());
        assertEquals("--memory: 'pooled' is not one of preallocated|allocating|scoped", error("--memory", "pooled"));
        assertTrue(error("--time-scale", "0").startsWith("--time-scale:"));
        assertTrue(error("--time-scale", "NaN").startsWith("--time-scale:"));
        // a deadline that rounds to its release, and releases past the clock's range (they overflowed)
        assertEquals("--time-scale: '1e-320' is out of range [1e-6, 1000]", error("--time-scale", "1e-320"));
        assertEquals("--time-scale: '1e300' is out of range [1e-6, 1000]", error("--time-scale", "1e300"));
        assertTrue(error("--warmup", "-1").startsWith("--warmup:"));
        assertTrue(error("-j", "../etc").startsWith("-j:"));
        assertTrue(error("-j", "..").startsWith("-j:"));
        String longName = new String(new char[300]).replace((char) 0, 'j');
        assertEquals("-j: 300 characters, longer than a folder name may be (255)", error("-j", longName),
                "as the C baseline says it, not blamed on -O when the run folder is made");
        assertEquals("-laser: missing: -odo, -laser and -real go together", error("-odo", "a", "-real", "c"));
        assertEquals("--dataset: cannot be combined with -odo/-laser/-real",
                error("--dataset", "d", "-odo", "a", "-laser", "b", "-real", "c"));
        assertEquals("-T: contradicts --policy queue", error("--policy", "queue", "-T"));
        assertEquals("--ideal: takes no value", error("--ideal=yes"));
        // only the Java SE release loop applies these; the scj and rtsj runs recorded them unapplied
        assertEquals("--spin-us: the scj engine does not spin before a release (only javase does)",
                error("--engine", "scj", "--spin-us", "100"));
        assertEquals("--gc-log: the rtsj engine writes no GC log (only javase does)", error("--engine", "rtsj", "--gc-log"));
        assertEquals("--load-alloc: the scj engine starts no allocation load (only javase does)",
                error("--engine", "scj", "--load-alloc", "50,8"));
        assertEquals("stray: unexpected argument (see --help)", error("stray"));
    }

    @Test
    void theMainReportsOptionErrorsWithExitCodeTwo() {
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        assertEquals(2, WorkloadMain.run(new String[] {"run", "--bogus"}, new PrintStream(out), new PrintStream(err)));
        assertEquals("jmclbench: --bogus: unknown option (see --help)\n",
                new String(err.toByteArray(), StandardCharsets.UTF_8).replace("\r", ""));
        err.reset();
        assertEquals(2, WorkloadMain.run(new String[] {"walk"}, new PrintStream(out), new PrintStream(err)));
        assertTrue(new String(err.toByteArray(), StandardCharsets.UTF_8).startsWith("jmclbench: walk: "));
        assertEquals(0, WorkloadMain.run(new String[] {"run", "--help"}, new PrintStream(out), new PrintStream(err)));
        assertTrue(new String(out.toByteArray(), StandardCharsets.UTF_8).contains("--particles"));
    }
}
