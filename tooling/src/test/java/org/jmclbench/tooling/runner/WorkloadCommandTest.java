package org.jmclbench.tooling.runner;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.List;

import org.jmclbench.tooling.runtime.RuntimeKind;
import org.jmclbench.tooling.load.LoadScenario;
import org.jmclbench.tooling.runtime.LaunchPlan;
import org.jmclbench.tooling.runtime.Profile;
import org.jmclbench.tooling.runtime.RuntimeInfo;
import org.junit.jupiter.api.Test;

/**
 * The native baseline is compared under the same scheduling as the JVMs unless a profile asks for FIFO;
 * the engine and memory style reach the workload only when they are not the defaults.
 */
class WorkloadCommandTest {
    private static final Path BIN = Path.of("/opt/jmclbench-native");
    private static final RuntimeInfo NATIVE = new RuntimeInfo("native", RuntimeKind.NATIVE, "jmclbench", "1",
            0, BIN, BIN);

    private static final Path JAVA = Path.of("/opt/jdk/bin/java");
    private static final RuntimeInfo JVM = new RuntimeInfo("temurin-25", RuntimeKind.JVM, "Eclipse Adoptium", "25+36",
            25, JAVA, JAVA);
    private static final RuntimeInfo HVM = new RuntimeInfo("hvm", RuntimeKind.HVM, "icecap", "1", 0, JAVA, JAVA);

    private static List<String> command(String profile) {
        return command(NATIVE, profile, Engines.NATIVE, Engines.PREALLOCATED);
    }

    private static List<String> command(RuntimeInfo rt, String profile, String engine, String memory) {
        Profile parsed = Profile.parse(profile, "--profiles");
        Profile p = parsed.effectiveFor(rt.kind());
        PlannedRun run = new PlannedRun(rt, p, engine, memory, "skip", 400, new Dataset("match-quick", Path.of("/d"), 10, "x"),
                1, 1, LoadScenario.NONE, "key");
        return WorkloadCommand.build(run, LaunchPlan.of(rt, p, "1"), List.of(), Path.of("/h"), Path.of("/w.jar"),
                Path.of("/out"), 1.0, List.of());
    }

    /** The value after {@code option} in {@code cmd}, or null. */
    private static String valueOf(List<String> cmd, String option) {
        int i = cmd.indexOf(option);
        return i < 0 ? null : cmd.get(i + 1);
    }

    @Test
    void javaSeEnginePreallocatedIsTheWorkloadsDefaultCommand() {
        List<String> cmd = command(JVM, "default", Engines.JAVASE, Engines.PREALLOCATED);
        assertFalse(cmd.contains("--engine"), cmd.toString());
        assertFalse(cmd.contains("--memory"), cmd.toString());
        assertEquals("temurin-25", valueOf(cmd, "-j"));
    }

    @Test
    void scjEngineAndMemoryStyleArePassedAndNameTheRun() {
        List<String> cmd = command(JVM, "default", Engines.SCJ, "scoped");
        assertEquals("scj", valueOf(cmd, "--engine"));
        assertEquals("scoped", valueOf(cmd, "--memory"));
        assertEquals("temurin-25-scj", valueOf(cmd, "-j"), "the -scj suffix of the workload's own default name");
        assertTrue(cmd.indexOf("--engine") > cmd.indexOf(WorkloadCommand.MAIN_CLASS), "a workload option, not a JVM flag");
    }

    @Test
    void nativeGetsItsMemoryStyleButNoEngine() {
        List<String> cmd = command(NATIVE, "default", Engines.NATIVE, "allocating");
        assertFalse(cmd.contains("--engine"), cmd.toString());
        assertEquals("allocating", valueOf(cmd, "--memory"));
        assertEquals("native", valueOf(cmd, "-j"));
    }

    @Test
    void nativeWithoutFifoProfileDoesNotRaiseItself() {
        List<String> cmd = command("default");
        assertTrue(cmd.contains("--no-fifo"), cmd.toString());
        assertFalse(cmd.contains("chrt"), cmd.toString());
    }

    @Test
    void nativeUnderFifoProfileRunsUnderChrt() {
        List<String> cmd = command("fifo");
        assertFalse(cmd.contains("--no-fifo"), cmd.toString());
        assertTrue(cmd.get(0).equals("chrt"), cmd.toString());
    }

    @Test
    void theHvmRunsAsTheWorkloadsHvmEngineOnTheToolsJava() {
        List<String> cmd = command(HVM, "g1+fifo", "hvm", Engines.PREALLOCATED);
        assertTrue(cmd.get(0).equals("chrt"), "the OS part of the profile applies: " + cmd);
        int java = cmd.indexOf(JAVA.toString());
        assertTrue(java > 0 && cmd.get(java + 1).equals("-Djmclbench.home=/h"), "no JVM flags of the profile: " + cmd);
        int run = cmd.indexOf("run");
        assertTrue(cmd.get(run - 1).equals(WorkloadCommand.MAIN_CLASS) && cmd.get(run + 1).equals("--engine")
                && cmd.get(run + 2).equals("hvm"), cmd.toString());
        assertFalse(cmd.contains("--no-fifo"), "the workload has no --no-fifo: " + cmd);
    }
}
