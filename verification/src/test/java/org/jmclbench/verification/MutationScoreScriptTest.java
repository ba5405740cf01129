package org.jmclbench.verification;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** mutation-score.py's command line: bad usage is one line naming the option and exit 2, before any copy or build. */
class MutationScoreScriptTest {
    private static final Path SCRIPT = Paths.get("mutation-score.py").toAbsolutePath();

    @TempDir
    Path dir;

    @Test
    void anUnknownOptionIsOneLine() throws Exception {
        // argparse printed its usage line first
        assertBad("mutation-score: unrecognized arguments: --bogus", "--bogus");
        assertBad("mutation-score: argument --only: expected one argument", "--only");
    }

    @Test
    void anEmptyOnlyIsOneLine() throws Exception {
        // it chose every mutant: an hour's run
        assertBad("mutation-score: --only: an empty mutant id (give ids, see --list)", "--only=");
    }

    @Test
    void aWorkBelowAFileIsOneLine() throws Exception {
        // os.makedirs ended in a traceback
        Files.writeString(dir.resolve("file"), "x");
        assertBad("mutation-score: --work: file/copy: " + dir.resolve("file").toRealPath() + " is not a folder",
                "--work", "file/copy");
    }

    @Test
    void everyMutantsTextStillOccursOnceInItsSource() throws Exception {
        // a refactoring that moves a mutant's line makes the whole score stop (exit 2) until someone runs it
        Process p = new ProcessBuilder("python3", SCRIPT.toString(), "--check").redirectErrorStream(true).start();
        String said = new String(p.getInputStream().readAllBytes());
        assertTrue(p.waitFor(60, TimeUnit.SECONDS), "mutation-score.py did not end");
        assertEquals(0, p.exitValue(), said);
        assertTrue(said.matches("mutation-score: \\d+ mutants, each text found once in its source\n"), said);
    }

    private void assertBad(String line, String... args) throws Exception {
        List<String> cmd = new ArrayList<>(List.of("python3", SCRIPT.toString()));
        cmd.addAll(List.of(args));
        Path out = dir.resolve("out.txt");
        Path err = dir.resolve("err.txt");
        Process p = new ProcessBuilder(cmd).directory(dir.toFile()).redirectOutput(out.toFile())
                .redirectError(err.toFile()).start();
        assertTrue(p.waitFor(60, TimeUnit.SECONDS), "mutation-score.py did not end");
        assertEquals(2, p.exitValue(), Files.readString(err));
        assertEquals(line + "\n", Files.readString(err));
        assertEquals("", Files.readString(out));
    }
}
