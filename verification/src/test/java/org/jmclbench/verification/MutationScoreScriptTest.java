package org.jmclbench.verification;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.nio.file.StandardCopyOption;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * mutation-score.py's command line (bad usage is one line naming the option and exit 2, before any
 * copy or build) and its verdicts, on a tree of one mission source with a fake Maven and verify.
 */
class MutationScoreScriptTest {
    private static final Path SCRIPT = Paths.get("mutation-score.py").toAbsolutePath();

    @TempDir
    Path dir;

    @Test
    void anUnknownOptionIsOneLine() throws Exception {
        // argparse printed its usage line first
        assertBad("mutation-score: unrecognized arguments: --bogus", "--bogus");
        assertBad("mutation-score: argument --only: expected one argument", "--only");
        assertBad("mutation-score: --retries: -1 is below 0", "--retries", "-1");
        assertBad("mutation-score: --unit-timeout: 0 is below 1", "--unit-timeout", "0");
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

    @Test
    void aCheckOverItsBudgetIsInconclusiveNotCaught() throws Exception {
        // the script counted any failing check as caught: a JPF search cut short by a loaded VM was a bug found
        Run r = score("over-budget");
        assertEquals(1, r.exit, r.out);
        assertTrue(r.out.contains("gate-ended-early                   INCONCLUSIVE verify: mission-skip over its budget"), r.out);
        assertTrue(r.out.contains("mutation score: 0 of 0 caught (0%), 1 inconclusive (not scored)\n"), r.out);
        assertTrue(r.out.contains("inconclusive: 1, run them again: --only gate-ended-early\n"), r.out);
    }

    @Test
    void aPropertyViolatedIsCaught() throws Exception {
        Run r = score("violation");
        assertEquals(0, r.exit, r.out);
        assertTrue(r.out.contains("gate-ended-early                   caught       verify: mission-skip (violation)"), r.out);
        assertTrue(r.out.contains("mutation score: 1 of 1 caught (100%), 0 inconclusive (not scored)\n"), r.out);
    }

    @Test
    void anInconclusiveMutantIsRunAgainWhenAsked() throws Exception {
        Run r = score("over-budget,violation", "--retries", "1");
        assertEquals(0, r.exit, r.out);
        assertTrue(r.out.contains("gate-ended-early                   inconclusive (verify: mission-skip over its budget), again\n"), r.out);
        assertTrue(r.out.contains("mutation score: 1 of 1 caught (100%), 0 inconclusive (not scored)\n"), r.out);
    }

    @Test
    void unitTestsKilledAfterTheirTimeoutAreInconclusiveUnlessACheckCatchesTheMutant() throws Exception {
        // a hang was counted caught: the tests of a loaded VM past the timeout scored as a bug found
        Run r = score("none", "--unit-timeout", "1");
        assertEquals(1, r.exit, r.out);
        assertTrue(r.out.contains("gate-ended-early                   INCONCLUSIVE unit tests killed after 1 s, verify passes"), r.out);
        Files.delete(dir.resolve("work/calls"));
        r = score("violation", "--unit-timeout", "1");
        assertEquals(0, r.exit, r.out);
        assertTrue(r.out.contains("caught       verify: mission-skip (violation); unit tests killed after 1 s"), r.out);
    }

    private record Run(int exit, String out) {
    }

    /**
     * The score of mutant gate-ended-early on a tree holding only JobGate.java: Maven's tests pass,
     * and verify passes without the mutant and fails mission-skip with it, once per call with
     * each of {@code failures} in turn (verify's failure field; "none" passes). With
     * {@code --unit-timeout}, Maven's tests hang on the mutant.
     */
    private Run score(String failures, String... args) throws Exception {
        Path tree = dir.resolve("tree");
        String gate = "scj-mission/src/main/java/org/jmclbench/scj/JobGate.java";
        Files.createDirectories(tree.resolve(gate).getParent());
        Files.copy(SCRIPT.getParent().getParent().resolve(gate), tree.resolve(gate), StandardCopyOption.REPLACE_EXISTING);
        Files.createDirectories(tree.resolve("verification"));
        Files.copy(SCRIPT, tree.resolve("verification/mutation-score.py"), StandardCopyOption.REPLACE_EXISTING);
        Path verify = tree.resolve("jmclbench");
        // verify's table line and, with --out, its results file
        Files.writeString(verify, """
                #!/bin/sh
                grep -q 'ended == events - 1' %s || exit 0
                echo x >> ../calls
                failure=$(echo "%s" | cut -d, -f$(wc -l < ../calls))
                [ "$failure" != none ] || exit 0
                while [ $# -gt 0 ]; do [ "$1" = --out ] && out=$2; shift; done
                echo "mission-skip                       P1 ended  skip      FAILS          0    120.0"
                [ -z "$out" ] || printf '{"checks": [{"id": "mission-skip", "passed": false, "failure": "%%s"}]}' \
                    "$failure" > "$out"
                exit 1
                """.formatted(gate, failures));
        Path bin = Files.createDirectories(dir.resolve("bin"));
        Files.writeString(bin.resolve("mvn"), "#!/bin/sh\n" + (List.of(args).contains("--unit-timeout")
                ? "! grep -q 'ended == events - 1' " + gate + " || sleep 60\n" : "") + "exit 0\n");
        for (Path f : List.of(verify, bin.resolve("mvn"))) {
            Files.setPosixFilePermissions(f, PosixFilePermissions.fromString("rwxr-xr-x"));
        }
        assertEquals(0, new ProcessBuilder("git", "init", "-q").directory(tree.toFile()).start().waitFor());
        List<String> cmd = new ArrayList<>(List.of("python3", tree.resolve("verification/mutation-score.py").toString(),
                "--only", "gate-ended-early", "--work", dir.resolve("work").toString()));
        cmd.addAll(List.of(args));
        ProcessBuilder pb = new ProcessBuilder(cmd).redirectErrorStream(true);
        pb.environment().put("PATH", bin + ":" + System.getenv("PATH"));
        Process p = pb.start();
        String out = new String(p.getInputStream().readAllBytes());
        assertTrue(p.waitFor(60, TimeUnit.SECONDS), "mutation-score.py did not end");
        return new Run(p.exitValue(), out);
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
