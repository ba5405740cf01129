package org.jmclbench.tooling.runner;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.concurrent.atomic.AtomicInteger;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * When a run that ended is an interruption (nothing recorded, the matrix stops) rather than the
 * runtime's failure: only when the runner is stopping, seen at once or within the grace after the
 * run's death by SIGHUP, SIGINT or SIGTERM. The stopping flag is given here as a sequence of answers,
 * so no test waits on a clock.
 */
class InterruptionTest {

    /** Answers false {@code falses} times, then true: the runner's hook sets the flag after the run died. */
    private static java.util.function.BooleanSupplier stopsAfter(int falses) {
        AtomicInteger asked = new AtomicInteger();
        return () -> asked.incrementAndGet() > falses;
    }

    @Test
    void aStoppingRunnerInterruptsWhateverTheExit() {
        for (int code : new int[] {0, 1, 137, 143}) {
            assertEquals("the runner was stopped", ForkedRun.interruption(code, () -> true, 0));
        }
    }

    /**
     * A system shutdown's SIGTERM ends the run before the runner's hook has run: the flag set just
     * after the run's death still makes it an interruption (without the grace, a failure was recorded).
     */
    @Test
    void aStopSeenWithinTheGraceAfterTheRunsDeathBySignalInterrupts() {
        assertEquals("the runner was stopped (SIGTERM)", ForkedRun.interruption(143, stopsAfter(1), 60_000));
        assertEquals("the runner was stopped (SIGINT)", ForkedRun.interruption(130, stopsAfter(2), 60_000));
        assertEquals("the runner was stopped (SIGHUP)", ForkedRun.interruption(129, stopsAfter(1), 60_000));
    }

    /** The runner not stopping: a death by any signal is the runtime's, as is any other exit. */
    @Test
    void aRunnerNotStoppingIsNoInterruption() {
        for (int code : new int[] {129, 130, 143, 137, 139, 1, 0}) {
            assertNull(ForkedRun.interruption(code, () -> false, 0), "exit " + code);
        }
    }

    /** Only a death by a stop signal waits for the runner's stop: a crash is recorded at once. */
    @Test
    void aCrashDoesNotWaitForTheRunnersStop() {
        assertNull(ForkedRun.interruption(139, stopsAfter(1), 60_000));
    }

    @Test
    void theStopSignalsAreNamedInTheFailure() {
        assertEquals("exit code 143: killed by SIGTERM", ForkedRun.describeExit(143, ""));
        assertEquals("exit code 130: killed by SIGINT", ForkedRun.describeExit(130, ""));
        assertEquals("exit code 129: killed by SIGHUP", ForkedRun.describeExit(129, ""));
        assertEquals("exit code 139: killed by SIGSEGV (crash)", ForkedRun.describeExit(139, ""));
    }

    /** A runner already stopping starts no run: its shutdown hook has run and would not kill it. */
    @Test
    void aStoppingRunnerStartsNoRun(@TempDir Path dir) {
        Path marker = dir.resolve("started");
        IOException e = assertThrows(IOException.class, () -> ForkedRun.execute(
                List.of("sh", "-c", "touch '" + marker + "'"), dir, dir.resolve("out"), 60, Map.of(), () -> true));
        assertTrue(e.getMessage().contains("was not started"), e.getMessage());
        assertFalse(Files.exists(marker));
    }

    /**
     * The hook ran while the run was being started (it found no run to kill): the run is killed
     * here, before anything waits on it, rather than outliving the runner in its own session.
     */
    @Test
    void aRunStartedAsTheRunnerStopsIsKilled(@TempDir Path dir) {
        String token = "jmclbench-started-as-stopping-" + ProcessHandle.current().pid();
        IOException e = assertThrows(IOException.class, () -> ForkedRun.execute(
                List.of("sh", "-c", "while :; do sleep 0.1; done # " + token), dir, dir.resolve("out"), 5, Map.of(),
                stopsAfter(1)));
        assertTrue(e.getMessage().contains("was not started"), e.getMessage());
        assertFalse(ProcessHandle.allProcesses().anyMatch(h -> h.isAlive()
                && h.info().commandLine().orElse("").contains(token)), "the run outlived the stop");
        assertNull(ForkedRun.CURRENT.get());
    }

    /** The aot profile's training run is adopted as a run is: started as the runner stops, it is killed. */
    @Test
    void aChildAdoptedAsTheRunnerStopsIsKilled() throws Exception {
        Process p = new ProcessBuilder("sleep", "600").start();
        try {
            assertFalse(ForkedRun.adopt(p, () -> true));
            assertFalse(p.isAlive());
            assertNull(ForkedRun.CURRENT.get());
        } finally {
            p.destroyForcibly();
        }
    }
}
