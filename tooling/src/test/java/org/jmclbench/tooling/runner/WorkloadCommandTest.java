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

    private static List<String> command(String profile) {
        Profile p = Profile.parse(profile, "--profiles");
        PlannedRun run = new PlannedRun(NATIVE, p, "skip", 400, new Dataset("match-quick", Path.of("/d"), 10, "x"),
                1, 1, LoadScenario.NONE, "key");
        return WorkloadCommand.build(run, LaunchPlan.of(NATIVE, p, "1"), List.of(), Path.of("/h"), Path.of("/w.jar"),
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
}
