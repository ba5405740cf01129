package org.jmclbench.workload;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;

import com.code_intelligence.jazzer.junit.FuzzTest;

/**
 * Jazzer target of the workload's command line (the thesis's short flags and the long
 * options): arguments are the input split at NUL bytes. Parsing either gives options that keep
 * the parser's promises or a one-line BadInputException naming the option; anything else (an
 * unchecked exception, a contradiction accepted) is a finding.
 */
class RunOptionsFuzzTest {
    @FuzzTest(maxDuration = "10m")
    void commandLine(byte[] data) {
        String[] args = new String(data, StandardCharsets.UTF_8).split("\0", -1);
        RunOptions o;
        try {
            o = RunOptionsParser.parse(args);
        } catch (BadInputException e) {
            String m = e.getMessage();
            assertTrue(!m.isEmpty() && m.indexOf('\n') < 0 && m.indexOf('\r') < 0, m);
            return;
        }
        if (o.help) {
            return;
        }
        assertTrue(o.particles >= 1 && o.number >= 0 && o.spinUs >= 0, "counts in range");
        assertTrue(o.timeScale > 0 && !Double.isInfinite(o.timeScale), "time scale");
        assertTrue(o.warmupS >= 0 && !Double.isInfinite(o.warmupS), "warm-up");
        int files = (o.odo != null ? 1 : 0) + (o.laser != null ? 1 : 0) + (o.real != null ? 1 : 0);
        assertTrue(files == 0 || files == 3, "-odo, -laser and -real together");
        assertFalse(files == 3 && o.dataset != null, "--dataset or the three files");
        assertTrue(o.runtimeName == null || o.runtimeName.matches("[A-Za-z0-9._+-]+"), "a runtime name is a folder");
        assertFalse(".".equals(o.runtimeName) || "..".equals(o.runtimeName), "a runtime name stays in the output root");
    }
}
