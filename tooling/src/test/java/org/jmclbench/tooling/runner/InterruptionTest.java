package org.jmclbench.tooling.runner;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;

import java.util.concurrent.atomic.AtomicInteger;

import org.junit.jupiter.api.Test;

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
}
