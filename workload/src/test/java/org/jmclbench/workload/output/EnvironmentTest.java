package org.jmclbench.workload.output;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/** The environment probe: /proc/.../stat parsing and what it reads on this machine. */
class EnvironmentTest {
    @Test
    void parsesPolicyAndPriorityEvenWithSpacesInTheCommand() {
        StringBuilder b = new StringBuilder("1234 (java (main) x) S");
        // Fields 4..39 are zero, then field 40 rt_priority = 20 and field 41 policy = 1 (FIFO).
        for (int f = 4; f <= 39; f++) {
            b.append(" 0");
        }
        b.append(" 20 1 0 0 0");
        assertArrayEquals(new int[] {1, 20}, Environment.parseStat(b.toString()));
        assertNull(Environment.parseStat("1 (x) S 1 2"));
        assertEquals("SCHED_FIFO", Environment.policyName(1));
        assertEquals("SCHED_OTHER", Environment.policyName(0));
    }

    @Test
    void capturesTheRuntimeAndTheMachine() {
        Environment e = Environment.capture();
        assertFalse(e.version.isEmpty());
        assertFalse(e.gcNames.isEmpty());
        assertTrue(e.processors >= 1);
        assertTrue(e.startedAt.matches("\\d{4}-\\d\\d-\\d\\dT\\d\\d:\\d\\d:\\d\\dZ"), e.startedAt);
        if (new java.io.File("/proc/self/stat").canRead()) {
            assertTrue(e.schedulingPolicy.startsWith("SCHED_"), e.schedulingPolicy);
            assertFalse(e.kernel.isEmpty());
        }
    }
}
