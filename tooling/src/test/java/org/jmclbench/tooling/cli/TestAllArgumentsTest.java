package org.jmclbench.tooling.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.Test;

/**
 * {@code ./jmclbench test} passes its arguments to Maven; one that Maven cannot parse is bad usage
 * at once (one line, exit 2), not a failure after the native tests have run.
 */
class TestAllArgumentsTest {

    @Test
    void anArgumentMavenCannotParseIsBadUsageBeforeAnyTestRuns() throws Exception {
        Path repo = Path.of(System.getProperty("user.dir")).toAbsolutePath().getParent();
        Process p = new ProcessBuilder(repo.resolve("scripts/test-all.sh").toString(), "--bogus").start();
        // were the argument let through, this would be the whole test suite again: stop it
        boolean ended = p.waitFor(120, TimeUnit.SECONDS);
        if (!ended) {
            p.descendants().forEach(ProcessHandle::destroyForcibly);
            p.destroyForcibly();
        }
        assertTrue(ended, "test-all ran on with an argument Maven cannot parse");
        String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        String err = new String(p.getErrorStream().readAllBytes(), StandardCharsets.UTF_8);
        assertEquals(2, p.exitValue(), err);
        assertEquals("test-all: Unable to parse command line options: Unrecognized option: --bogus", err.strip());
        assertFalse(out.contains("== native tests"), "nothing ran: " + out);
    }
}
