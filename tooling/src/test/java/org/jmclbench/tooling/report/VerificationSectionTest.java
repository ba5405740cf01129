package org.jmclbench.tooling.report;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.nio.file.Files;
import java.nio.file.Path;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

class VerificationSectionTest {

    @Test
    void noSectionWithoutVerifyResults(@TempDir Path dir) throws Exception {
        assertEquals("", VerificationSection.html(dir));
    }

    @Test
    void showsEachCheckVerdictEscaped(@TempDir Path dir) throws Exception {
        Files.writeString(dir.resolve("verification.json"), """
                {"schema":1,"finished":"2026-11-23T13:00:00Z","passed":false,"checks":[
                 {"id":"mission-queue","property":"P1 no deadlock","policy":"queue","kind":"jpf","seeded":false,
                  "verdict":"holds","passed":true,"seconds":12.5,"states":1465},
                 {"id":"seed<x>","property":"P6 <script>","policy":"-","kind":"static","seeded":true,
                  "verdict":"MISSED","passed":false,"seconds":0.1}]}
                """);
        String html = VerificationSection.html(dir);
        assertTrue(html.contains("<td>mission-queue</td><td>P1 no deadlock</td><td>queue</td><td>jpf</td><td>holds</td><td>1465</td><td>12.5</td>"), html);
        assertTrue(html.contains("<tr class=\"fail\"><td>seed&lt;x&gt;</td><td>P6 &lt;script&gt;</td>"), html);
        assertTrue(html.contains("some checks failed"), html);
        assertFalse(html.contains("<script>"), html);
    }
}
