package org.jmclbench.tooling.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;

import java.nio.file.Files;
import java.nio.file.Path;

import org.jmclbench.tooling.Fixtures;
import org.jmclbench.tooling.Fixtures.CliResult;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The command line's own handling of bad input: one line, exit code 2, whatever the input holds. */
class JmclbenchCliTest {

    @TempDir
    Path tmp;

    private static void assertOneLine(String expected, CliResult r) {
        assertEquals(2, r.exitCode(), r.err());
        assertEquals(1, r.err().lines().count(), "one line: " + r.err());
        assertEquals(expected, r.err().strip());
    }

    @Test
    void aNewlineOrTabInAPathOrValueIsEscapedNotPrinted() throws Exception {
        // a command's own refusal (BadUsageException): the path broke it into "--out: .../f" and "x exists ..."
        Path file = Files.writeString(tmp.resolve("f\nx"), "a file");
        assertOneLine("jmclbench: --out: " + tmp + "/f\\nx exists and is not a folder",
                Fixtures.cli("generate", "--scenario", "match", "--out", file.toString()));
        assertOneLine("jmclbench: --scenario: unknown scenario 'a\\tb\\r\\nc\\u001b'"
                        + " (known: match, match-short, match-quick, stay, figure8, kidnap)",
                Fixtures.cli("generate", "--scenario", "a\tb\r\nc\u001b", "--out", tmp.resolve("y").toString()));
        // picocli's refusal of a value
        assertOneLine("jmclbench: Invalid value for option '--seed': '1\\n5' is not a long",
                Fixtures.cli("generate", "--scenario", "match", "--out", tmp.resolve("y").toString(), "--seed", "1\n5"));
        assertFalse(Files.exists(tmp.resolve("y")), "nothing written");
    }

    @Test
    void anEmptyPathIsRefusedNotTakenForTheWorkingFolder() throws Exception {
        // Path.of("") is the working folder: report and evaluate wrote there (evaluate's document in its parent)
        Path db = Files.writeString(tmp.resolve("results.db"), "not read: the value is refused first");
        assertOneLine("jmclbench: Invalid value for option '--out': an empty path ('.' names the working folder)",
                Fixtures.cli("report", "--db", db.toString(), "--out", "", "--no-export"));
        assertOneLine("jmclbench: Invalid value for option '--out': an empty path ('.' names the working folder)",
                Fixtures.cli("evaluate", "--no-run", "--out", ""));
        assertOneLine("jmclbench: Invalid value for option '--into': an empty path ('.' names the working folder)",
                Fixtures.cli("merge", db.toString(), "--into", ""));
        assertOneLine("jmclbench: Invalid value for positional parameter at index 0 (RUN_DIR): an empty path"
                + " ('.' names the working folder)", Fixtures.cli("explain", ""));
        assertFalse(Files.exists(Path.of("index.html")), "nothing written in the working folder");
    }

    @Test
    void aBackslashOrAnAccentStaysAsItIsAndUnicodeLineBreaksAreEscaped() {
        String known = " (known: match, match-short, match-quick, stay, figure8, kidnap)";
        String out = tmp.resolve("y").toString();
        assertOneLine("jmclbench: --scenario: unknown scenario '/a\\b/c \u00e9'" + known,
                Fixtures.cli("generate", "--scenario", "/a\\b/c \u00e9", "--out", out));
        assertOneLine("jmclbench: --scenario: unknown scenario 'a\\u2028b\\u0085c\\u007f'" + known,
                Fixtures.cli("generate", "--scenario", "a\u2028b\u0085c\u007f", "--out", out));
    }
}
