package org.jmclbench.core.policy;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;

import org.junit.jupiter.api.Test;

class OverrunPolicyTest {

    @Test
    void codesAndLabelsAreStableAndFindTheirPolicy() {
        // the codes are in files (the HVM run file) and in C: they never change
        assertEquals(0, OverrunPolicy.SKIP.code);
        assertEquals(1, OverrunPolicy.TERMINATE.code);
        assertEquals(2, OverrunPolicy.QUEUE.code);
        assertEquals("SkipTest", OverrunPolicy.SKIP.folder);
        assertEquals("TermTest", OverrunPolicy.TERMINATE.folder);
        assertEquals("QueueTest", OverrunPolicy.QUEUE.folder);
        for (OverrunPolicy p : OverrunPolicy.values()) {
            assertSame(p, OverrunPolicy.ofCode(p.code));
            assertSame(p, OverrunPolicy.ofLabel(p.label));
        }
    }

    /** The thesis's missCount, as the C baseline's jm_policy_misses counts it: queue its late jobs, the others what they dropped or aborted. */
    @Test
    void missCountIsWhatEachPolicysTestCounted() {
        assertEquals(5 + 7, OverrunPolicy.SKIP.missCount(3, 5, 7));
        assertEquals(5 + 7, OverrunPolicy.TERMINATE.missCount(3, 5, 7));
        assertEquals(3, OverrunPolicy.QUEUE.missCount(3, 5, 7));
    }

    @Test
    void unknownCodesAndLabelsFindNothing() {
        int unused = 0; // the code after the highest, whatever policies there are
        for (OverrunPolicy p : OverrunPolicy.values()) {
            unused = Math.max(unused, p.code + 1);
        }
        assertNull(OverrunPolicy.ofCode(unused));
        assertNull(OverrunPolicy.ofCode(-1));
        assertNull(OverrunPolicy.ofCode(1L << 32)); // not aliased to 0 by a narrowing cast
        assertNull(OverrunPolicy.ofLabel("SKIP"));
        assertNull(OverrunPolicy.ofLabel(null));
    }

    /** The C baseline's one definition (native/src/policy.h) has the same codes, labels and test names. */
    @Test
    void theCBaselineDefinesTheSamePolicies() throws IOException {
        Path header = Paths.get("..", "native", "src", "policy.h");
        String c = new String(Files.readAllBytes(header), StandardCharsets.UTF_8);
        StringBuilder labels = new StringBuilder();
        for (OverrunPolicy p : OverrunPolicy.values()) {
            String constant = "JM_POLICY_" + p.name();
            assertTrue(c.contains(constant + " = " + p.code), constant + " = " + p.code + " in " + header);
            labels.append(labels.length() == 0 ? "" : "|").append(p.label);
            assertTrue(c.contains("[" + constant + "] = { \"" + p.label + "\", \"" + p.folder + "\" },"),
                    constant + "'s row in jm_policy_table: " + p.label + ", " + p.folder);
        }
        assertTrue(c.contains("#define JM_POLICY_LABELS \"" + labels + "\""), "labels in code order: " + labels);
    }

    /** Skip: one admitted event at a time, from its release to its job's end; nothing waits or aborts. */
    @Test
    void skipReservesTheRobotFromReleaseToEnd() {
        OverrunPolicy.State s = new OverrunPolicy.State(OverrunPolicy.SKIP, true);
        assertTrue(s.admit(0, false));
        assertFalse(s.admit(1, false), "the robot is reserved by 0, started or not");
        s.ended(1); // not the holder: changes nothing
        assertFalse(s.admit(2, false));
        assertEquals(OverrunPolicy.START, OverrunPolicy.SKIP.start(s, 0));
        assertFalse(OverrunPolicy.SKIP.abortRequested(s, 0));
        s.ended(0);
        assertFalse(s.admit(3, true), "the engine judged the robot busy");
        assertTrue(s.admit(4, false));
        assertEquals(OverrunPolicy.State.FREE, s.superseded());
        assertFalse(OverrunPolicy.SKIP.abortsJobInProgress());
        assertFalse(OverrunPolicy.SKIP.eventsWait());
    }

    /** Terminate: every release is admitted and supersedes the previous latest, whose job is asked to abort. */
    @Test
    void terminateSupersedesThePreviousEvent() {
        OverrunPolicy.State s = new OverrunPolicy.State(OverrunPolicy.TERMINATE, true);
        assertTrue(s.admit(0, true), "busy does not drop under terminate");
        assertEquals(OverrunPolicy.State.FREE, s.superseded());
        assertFalse(OverrunPolicy.TERMINATE.abortRequested(s, 0));
        assertTrue(s.admit(1, false));
        assertEquals(0, s.superseded());
        assertTrue(OverrunPolicy.TERMINATE.abortRequested(s, 0));
        assertFalse(OverrunPolicy.TERMINATE.abortRequested(s, 1));
        s.ended(0);
        assertTrue(s.admit(2, false));
        assertEquals(1, s.superseded());
        assertEquals(OverrunPolicy.START, OverrunPolicy.TERMINATE.start(s, 2));
        assertTrue(OverrunPolicy.TERMINATE.abortsJobInProgress());
        assertTrue(OverrunPolicy.TERMINATE.eventsWait());
    }

    /** Queue: everything admitted, nothing aborted; an ordered state hands the robot in release order. */
    @Test
    void queueHandsTheRobotInReleaseOrderWhenOrdered() {
        OverrunPolicy.State s = new OverrunPolicy.State(OverrunPolicy.QUEUE, true);
        for (int k = 0; k < 3; k++) {
            assertTrue(s.admit(k, true));
            assertEquals(OverrunPolicy.State.FREE, s.superseded());
        }
        assertEquals(OverrunPolicy.START, OverrunPolicy.QUEUE.start(s, 0));
        assertEquals(OverrunPolicy.WAIT, OverrunPolicy.QUEUE.start(s, 1));
        s.ended(0);
        assertEquals(OverrunPolicy.START, OverrunPolicy.QUEUE.start(s, 1));
        assertEquals(OverrunPolicy.WAIT, OverrunPolicy.QUEUE.start(s, 2));
        assertFalse(OverrunPolicy.QUEUE.abortRequested(s, 1));
        assertFalse(OverrunPolicy.QUEUE.abortsJobInProgress());

        OverrunPolicy.State lock = new OverrunPolicy.State(OverrunPolicy.QUEUE, false);
        assertTrue(lock.admit(0, false) && lock.admit(1, false));
        assertEquals(OverrunPolicy.START, OverrunPolicy.QUEUE.start(lock, 1), "unordered: the engine's lock orders");
    }

    /** Whatever a policy's rule, a lone event is admitted, may start, is not aborted, and frees the robot. */
    @Test
    void everyPolicyRunsALoneEvent() {
        for (OverrunPolicy p : OverrunPolicy.values()) {
            for (boolean ordered : new boolean[] {true, false}) {
                OverrunPolicy.State s = new OverrunPolicy.State(p, ordered);
                assertSame(p, s.policy());
                for (int k = 0; k < 3; k++) {
                    assertTrue(s.admit(k, false), p + ": event " + k + " alone");
                    assertEquals(OverrunPolicy.START, p.start(s, k), p + ": event " + k);
                    assertFalse(p.abortRequested(s, k), p + ": event " + k);
                    s.ended(k);
                }
            }
        }
    }
}
