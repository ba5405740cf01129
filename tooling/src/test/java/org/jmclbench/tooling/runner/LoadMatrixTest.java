package org.jmclbench.tooling.runner;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Map;

import org.jmclbench.tooling.Fixtures;
import org.junit.jupiter.api.Test;

/** The load dimension of the matrix: planned, recorded with each run, passed to the workload, ended with the run. */
class LoadMatrixTest extends FakeJvmHome {

    @Test
    void anUnknownLoadIsBadUsage() {
        Fixtures.CliResult r = Fixtures.cli("matrix", "--java", fake.toString(), "--load", "none,gpu",
                "--datasets", "tiny", "--db", db.toString());
        assertEquals(2, r.exitCode(), r.out() + r.err());
        assertEquals("jmclbench: --load: 'gpu' is not one of none, cpu, alloc, mixed", r.err().strip());
        assertFalse(Files.exists(db));
    }

    @Test
    void aBadAllocLoadIsBadUsage() {
        Fixtures.CliResult r = Fixtures.cli("matrix", "--java", fake.toString(), "--load", "alloc", "--load-alloc", "50",
                "--datasets", "tiny", "--db", db.toString());
        assertEquals(2, r.exitCode(), r.out() + r.err());
        assertEquals("jmclbench: --load-alloc: '50' must be MBPS,LIVEMB (e.g. 100,16)", r.err().strip());
    }

    @Test
    void eachLoadIsOneMoreRunOfEachConfiguration() {
        Fixtures.CliResult r = Fixtures.cli("matrix", "--java", fake.toString(), "--load", "none,cpu,alloc",
                "--datasets", "tiny", "--dry-run", "--db", db.toString());
        assertEquals(0, r.exitCode(), r.err());
        assertTrue(r.out().startsWith("3 runs planned"), r.out());
        assertTrue(r.out().contains("fake-21 default skip 400p tiny load=cpu #1"), r.out());
        assertTrue(r.out().contains("fake-21 default skip 400p tiny #1"), r.out());
    }

    @Test
    void theAllocationLoadIsUnsupportedOutsideTheJavaSeEngine() throws Exception {
        // the scj and rtsj engines ran without it and recorded the run under load alloc
        Path store = db.resolveSibling("engines.db");
        Fixtures.CliResult r = Fixtures.cli("matrix", "--java", fake.toString(), "--engines", "javase,scj,rtsj",
                "--load", "alloc", "--load-alloc", "50,8", "--datasets", "tiny", "--db", store.toString());
        assertEquals(0, r.exitCode(), r.out() + r.err());
        Map<String, String> statusByEngine = Fixtures.columns(store, "SELECT engine, status || coalesce(': ' || failure, '') FROM runs");
        assertEquals("ok", statusByEngine.get("javase"), statusByEngine.toString());
        for (String engine : new String[] {"scj", "rtsj"}) {
            assertEquals("unsupported: load alloc: the allocation load runs only in the Java SE engine (javase on a JVM)",
                    statusByEngine.get(engine), statusByEngine.toString());
        }
    }

    @Test
    void theLoadIsRecordedPassedToTheWorkloadAndEndsWithTheRun() throws Exception {
        Fixtures.CliResult r = Fixtures.cli("matrix", "--java", fake.toString(), "--load", "cpu,alloc",
                "--load-alloc", "50,8", "--datasets", "tiny", "--db", db.toString());
        assertEquals(0, r.exitCode(), r.out() + r.err());
        Fixtures.columns(db, "SELECT load, status FROM runs").forEach((load, status) -> assertEquals("ok", status, load));
        Map<String, String> commands = Fixtures.columns(db, "SELECT load, command_json FROM runs");
        assertEquals(2, commands.size(), commands.toString());
        assertTrue(commands.get("alloc").contains("\"--load-alloc\",\"50,8\""), commands.get("alloc"));
        assertTrue(commands.get("cpu").contains("\"--load-name\",\"cpu\""), commands.get("cpu"));
        assertTrue(commands.get("cpu").contains("-XX:StartFlightRecording=filename="), "JDK 11+: a JFR recording");
        assertTrue(ProcessHandle.current().descendants().noneMatch(p -> p.info().command().orElse("").endsWith("stress-ng")),
                "no CPU hog outlives its run");
    }
}
