package org.jmclbench.tooling.runner;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.nio.file.Path;
import java.util.Map;

import org.jmclbench.tooling.Fixtures;
import org.jmclbench.tooling.runtime.IdleStateHold;
import org.junit.jupiter.api.Test;

/**
 * The noidle profile holds /dev/cpu_dma_latency open while its run lasts, and only then: the fake
 * runtime fails unless some process holds the device. Where the device is root's and we are not
 * root, the noidle run is unsupported, with the reason.
 */
class NoIdleProfileTest extends FakeJvmHome {

    @Test
    void theDeviceIsHeldDuringANoidleRunAndNotOtherwise() throws Exception {
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
}
