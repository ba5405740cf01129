package org.jmclbench.verification.jpf;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.List;
import java.util.Map;
import java.util.Set;

import org.jmclbench.verification.Property;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * A JVM under JPF that crashes is that check's failure, never verify's: HotSpot writes its
 * hs_err_pid file into the working directory, which JpfRunner then failed to delete.
 */
class JpfRunnerCrashTest {
    @TempDir
    Path dir;

    @Test
    void aCrashedJvmIsTheChecksFailureAndItsReportIsKept() throws Exception {
        // a "java" that does what a crashing HotSpot does: a report in its working directory, exit 134
        Path java = dir.resolve("java");
        Files.writeString(java, "#!/bin/sh\necho 'A fatal error has been detected by the Java Runtime Environment'\n"
                + "echo '# internal error' > hs_err_pid4242.log\nexit 134\n");
        Files.setPosixFilePermissions(java, PosixFilePermissions.fromString("rwxr-xr-x"));
        Path logs = dir.resolve("logs");
        JpfRunner runner = new JpfRunner(new JpfHome(dir, java), List.of(), logs, 60, 64);
        JpfCheck check = new JpfCheck("crash-check", Set.of(Property.P1), "-", "some.Main", List.of(), Map.of(),
                JpfCheck.Expectation.holds(), "-");

        JpfResult r = runner.run(check);

        assertFalse(r.passed());
        assertTrue(r.verdict().startsWith("FAILED: JPF ended (exit 134) without a verdict"), r.verdict());
        assertEquals(JpfResult.Failure.NO_VERDICT, r.failure(), "a crash is a failure of the check, not a run cut short");
        assertEquals("# internal error\n", Files.readString(logs.resolve("crash-check.hs_err_pid4242.log")));
    }

    @Test
    void aCheckGivenMoreBudgetRunsPastTheRunsBudgetAndNotForever() throws Exception {
        // a "java" that searches for 3 s and writes no verdict; the run's budget is 1 s
        Path java = dir.resolve("java");
        Files.writeString(java, "#!/bin/sh\nsleep 3\nexit 0\n");
        Files.setPosixFilePermissions(java, PosixFilePermissions.fromString("rwxr-xr-x"));
        JpfRunner runner = new JpfRunner(new JpfHome(dir, java), List.of(), dir.resolve("logs"), 1, 64);
        JpfCheck check = new JpfCheck("slow-check", Set.of(Property.P1), "-", "some.Main", List.of(), Map.of(),
                JpfCheck.Expectation.holds(), "-");

        JpfResult over = runner.run(check);
        assertEquals("FAILED: over the 1 s budget", over.verdict(), "stopped at the run's budget");
        // what the mutation score reads to call a mutant inconclusive, not caught
        assertEquals(JpfResult.Failure.OVER_BUDGET, over.failure());
        // given 5 times the budget it runs to its end (here: no verdict, a failure of another kind)
        assertTrue(runner.run(check.withBudgetFactor(5)).verdict().startsWith("FAILED: JPF ended (exit 0) without a verdict"));
    }
}
