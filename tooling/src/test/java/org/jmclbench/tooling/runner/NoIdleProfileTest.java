package org.jmclbench.tooling.runner;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.IOException;
import java.nio.file.Path;
import java.util.Map;

import org.jmclbench.tooling.Fixtures;
import org.jmclbench.tooling.runtime.IdleStateHold;
import org.junit.jupiter.api.Test;

/**
 * The noidle profile holds /dev/cpu_dma_latency open while its run lasts, and only then: the fake
 * runtime fails unless the runner's JVM holds the device. Where the device is root's and we are not
 * root, the noidle run is unsupported, with the reason.
 */
class NoIdleProfileTest extends FakeJvmHome {

    @Test
    void theDeviceIsHeldDuringANoidleRunAndNotOtherwise() throws Exception {
        defaultFailsAndNoidleHolds();
    }

    /**
     * Another process holding the device (tuned, a cyclictest left running) is not the runner's
     * request: the default run still finds the device unheld by the runner.
     */
    @Test
    void anotherProcessHoldingTheDeviceIsNotTheRunsHold() throws Exception {
        assumeTrue(IdleStateHold.unavailable(IdleStateHold.DEVICE) == null,
                "another process can hold " + IdleStateHold.DEVICE + " only where it is writable");
        Process holder = new ProcessBuilder("bash", "-c", "exec 3>" + IdleStateHold.DEVICE + "; exec sleep 600")
                .redirectErrorStream(true).start();
        try {
            long deadline = System.nanoTime() + 30_000_000_000L;
            while (!holds(holder.pid()) && holder.isAlive() && System.nanoTime() < deadline) {
                Thread.sleep(20);
            }
            assertTrue(holds(holder.pid()), "the holder never opened " + IdleStateHold.DEVICE);
            defaultFailsAndNoidleHolds();
            assertTrue(holds(holder.pid()), "the holder let go of " + IdleStateHold.DEVICE + " during the runs");
        } finally {
            holder.destroyForcibly().waitFor();
        }
    }

    private void defaultFailsAndNoidleHolds() throws Exception {
        Path idle = Fixtures.fakeJava(dir, "idle", "idleheld", 0, null, 21);
        Fixtures.CliResult r = Fixtures.cli("matrix", "--datasets", "tiny", "--particles", "100", "--timeout", "15",
                "--profiles", "default,noidle", "--db", db.toString(), "--java", idle.toString());
        assertEquals(0, r.exitCode(), r.out() + r.err());
        Map<String, String> outcomes = Fixtures.columns(db, "SELECT profile, status || ': ' || coalesce(failure, '') FROM runs");
        assertEquals("failed: exit code 1: jmclbench: failure: nobody holds /dev/cpu_dma_latency", outcomes.get("default"),
                outcomes.toString());
        String why = IdleStateHold.unavailable(IdleStateHold.DEVICE);
        assertEquals(why == null ? "ok: " : "unsupported: " + why, outcomes.get("noidle"), outcomes.toString());
    }

    /** Whether process {@code pid} has the device open. */
    private static boolean holds(long pid) throws IOException {
        return Fixtures.openDescriptors(Long.toString(pid), IdleStateHold.DEVICE) > 0;
    }
}
