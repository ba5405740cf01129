package org.jmclbench.core.policy;

import static org.junit.jupiter.api.Assertions.assertEquals;
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
}
