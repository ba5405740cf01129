package org.jmclbench.tooling.runner;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.List;

import org.jmclbench.tooling.load.LoadScenario;
import org.jmclbench.tooling.runtime.LaunchPlan;
import org.jmclbench.tooling.runtime.Profile;
import org.jmclbench.tooling.runtime.RuntimeInfo;
import org.junit.jupiter.api.Test;

/** The native baseline is compared under the same scheduling as the JVMs unless a profile asks for FIFO. */
class WorkloadCommandTest {
    private static final Path BIN = Path.of("/opt/jmclbench-native");
    private static final RuntimeInfo NATIVE = new RuntimeInfo("native", RuntimeInfo.Kind.NATIVE, "jmclbench", "1",
            0, BIN, BIN);

    private static final Path JAVA = Path.of("/usr/bin/java");
    private static final RuntimeInfo HVM = new RuntimeInfo("hvm", RuntimeInfo.Kind.HVM, "icecap", "1", 0, JAVA, JAVA);

    private static List<String> command(String profile) {
        return command(NATIVE, profile);
    }

    private static List<String> command(RuntimeInfo rt, String profile) {
        Profile p = Profile.parse(profile, "--profiles").forNative();
        PlannedRun run = new PlannedRun(rt, p, "skip", 400, new Dataset("match-quick", Path.of("/d"), 10, "x"),
                1, 1, LoadScenario.NONE, "key");
        return WorkloadCommand.build(run, LaunchPlan.of(rt, p, "1"), List.of(), Path.of("/h"), Path.of("/w.jar"),
                Path.of("/out"), 1.0, List.of());
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
        List<String> cmd = command(HVM, "g1+fifo");
        assertTrue(cmd.get(0).equals("chrt"), "the OS part of the profile applies: " + cmd);
        int java = cmd.indexOf(JAVA.toString());
        assertTrue(java > 0 && cmd.get(java + 1).equals("-Djmclbench.home=/h"), "no JVM flags of the profile: " + cmd);
        int run = cmd.indexOf("run");
        assertTrue(cmd.get(run - 1).equals(WorkloadCommand.MAIN_CLASS) && cmd.get(run + 1).equals("--engine")
                && cmd.get(run + 2).equals("hvm"), cmd.toString());
        assertFalse(cmd.contains("--no-fifo"), "the workload has no --no-fifo: " + cmd);
    }
}
