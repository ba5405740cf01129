package org.jmclbench.verification;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.File;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * {@code jmclbench verify}'s command line: bad input is one line on stderr and exit 2, before any
 * check runs or its table starts. A forked JVM, since the command ends with System.exit.
 */
class VerifyMainTest {
    @TempDir
    Path dir;

    @Test
    void anOnlyPrefixNoCheckHasIsOneLineAndNoTable() throws Exception {
        assertBadInput("jmclbench: verify: --only: no check id starts with no-such-check or nor-this",
                "--only", "no-such-check,nor-this");
    }

    @Test
    void aTimeoutThatIsNotAPositiveNumberIsOneLine() throws Exception {
        assertBadInput("jmclbench: verify: Invalid value for option '--timeout': '0' is not a positive number",
                "--timeout", "0");
        assertBadInput("jmclbench: verify: Missing required parameter for option '--heap' (MB)", "--heap");
    }

    @Test
    void anUnknownOptionIsNamedAsUnknown() throws Exception {
        // the hand-written parser took it for an option that needs a value
        assertBadInput("jmclbench: verify: Unknown option: '--bogus'", "--bogus");
    }

    private void assertBadInput(String message, String... args) throws Exception {
        Path out = dir.resolve("out.txt");
        Path err = dir.resolve("err.txt");
        List<String> cmd = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "-cp", System.getProperty("java.class.path"), VerifyMain.class.getName()));
        cmd.addAll(List.of(args));
        Process p = new ProcessBuilder(cmd).directory(dir.toFile()).redirectOutput(out.toFile())
                .redirectError(err.toFile()).start();
        assertTrue(p.waitFor(120, TimeUnit.SECONDS), "verify did not end");
        assertEquals(2, p.exitValue(), Files.readString(err));
        assertEquals(List.of(message), Files.readAllLines(err, StandardCharsets.UTF_8));
        assertEquals("", Files.readString(out), "nothing on stdout: no table header before the error");
        assertFalse(new File(dir.toFile(), "results").exists(), "no verification.json for bad input");
    }
}
