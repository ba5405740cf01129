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

import org.junit.jupiter.api.Assumptions;
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
    void anOnlyPrefixNoCheckHasIsNamedBesideOneThatHas() throws Exception {
        // the misspelt prefix selected nothing and the run passed on the other one's checks
        assertBadInput("jmclbench: verify: --only: no check id starts with P2-statc", "--only", "P2-static,P2-statc");
    }

    @Test
    void anOutWhereNothingCanBeWrittenIsOneLineBeforeAnyCheck() throws Exception {
        // it was a stack trace and exit 1 after every check had run (root writes any ordinary
        // folder, so the unwritable place is /proc)
        Assumptions.assumeTrue(Files.isDirectory(Path.of("/proc/self")), "no /proc here");
        assertBadInput("jmclbench: verify: --out: /proc/verification.json: cannot write in /proc (NoSuchFileException)",
                "--only", "P2-static", "--out", "/proc/verification.json");
    }

    @Test
    void aTimeoutThatIsNotAPositiveNumberIsOneLine() throws Exception {
        assertBadInput("jmclbench: verify: Invalid value for option '--timeout': '0' is not a positive number",
                "--timeout", "0");
        assertBadInput("jmclbench: verify: Missing required parameter for option '--heap' (MB)", "--heap");
    }

    @Test
    void aHeapNoJvmCanReserveIsOneLineBeforeAnyCheck() throws Exception {
        // every JPF check failed (exit 1, "verification: 0 passed, 1 failed"): a failure of the
        // benchmark for what is bad usage
        assertBadInput("jmclbench: verify: --heap: 2147483647 MB: no JVM starts with it"
                + " (Could not reserve enough space for 2199023255552KB object heap)",
                "--only", "mission-seeded-stray-allocation", "--heap", "2147483647");
    }

    @Test
    void anEmptyPathIsOneLineNamingTheOption() throws Exception {
        // --logs "" was the working folder; --out "" said '--out:  is a folder' (an unset "$DIR")
        String empty = "an empty path ('.' names the working folder)";
        assertBadInput("jmclbench: verify: Invalid value for option '--logs': " + empty, "--only", "P2-static", "--logs", "");
        assertBadInput("jmclbench: verify: Invalid value for option '--out': " + empty, "--only", "P2-static", "--out", "");
    }

    @Test
    void anUnknownOptionIsNamedAsUnknown() throws Exception {
        // the hand-written parser took it for an option that needs a value
        assertBadInput("jmclbench: verify: Unknown option: '--bogus'", "--bogus");
    }

    @Test
    void anEmptyOnlyPrefixIsOneLine() throws Exception {
        // it selected every check: a whole run, written nowhere as a partial one
        String message = "jmclbench: verify: --only: an empty prefix selects every check"
                + " (give check id prefixes, for example mission-,P4)";
        assertBadInput(message, "--only=");
        assertBadInput(message, "--only", ",");
    }

    @Test
    void anOutBelowAFileIsOneLineBeforeAnyCheck() throws Exception {
        // it was a stack trace and exit 1 after every check had run
        Files.writeString(dir.resolve("file"), "x");
        assertBadInput("jmclbench: verify: --out: file/v.json: " + dir.resolve("file").toRealPath() + " is not a folder",
                "--only", "P2-static", "--out", "file/v.json");
    }

    @Test
    void anOutThatIsAFolderIsOneLineAndTheFolderStays() throws Exception {
        // an empty folder was replaced by the results file
        Files.createDirectory(dir.resolve("folder"));
        assertBadInput("jmclbench: verify: --out: folder is a folder, not a results file",
                "--only", "P2-static", "--out", "folder");
        assertTrue(Files.isDirectory(dir.resolve("folder")));
    }

    @Test
    void logsThatAreAFileAreOneLine() throws Exception {
        // the first JPF check threw FileAlreadyExistsException, after the static checks
        Files.writeString(dir.resolve("file"), "x");
        assertBadInput("jmclbench: verify: --logs: file is not a folder", "--only", "P2-static", "--logs", "file");
        assertBadInput("jmclbench: verify: --logs: file/logs: " + dir.resolve("file").toRealPath() + " is not a folder",
                "--only", "P2-static", "--logs", "file/logs");
    }

    /**
     * Java PathFinder not there, by a path the user gave: -Djpf.home or JPF_HOME naming no folder, or a
     * folder with only part of a build (jpf.jar without the model classes), -Djpf.java naming no
     * java: one line naming the path and how to get a build, exit 2, before any check and with no
     * results file. Each was an IllegalStateException's stack trace, exit 1; the partial build ran
     * the checks, each failing with no verdict, and wrote them to the results file.
     */
    @Test
    void aJpfHomeOrJavaTheUserGaveThatIsNoBuildIsOneLineAndExit2() throws Exception {
        String how = "verification/build-jpf.sh builds one (JPF_CORE_SRC: a jpf-core folder or tarball such as"
                + " jpf-core-7ea25de.tar.gz; ./jmclbench verify runs it)";
        Path nowhere = dir.resolve("nowhere");
        assertJpfMissing(2, "jmclbench: verify: -Djpf.home=" + nowhere + ": no Java PathFinder build there (no such folder); "
                + how, List.of("-Djpf.home=" + nowhere), null);
        assertJpfMissing(2, "jmclbench: verify: JPF_HOME=" + nowhere + ": no Java PathFinder build there (no such folder); "
                + how, List.of(), nowhere.toString());
        Path partial = Files.createDirectories(dir.resolve("partial/build"));
        byte[] emptyJar = {'P', 'K', 5, 6, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0};
        Files.write(partial.resolve("jpf.jar"), emptyJar);
        assertJpfMissing(2, "jmclbench: verify: -Djpf.home=" + partial.getParent() + ": no Java PathFinder build there"
                + " (no build/jpf-classes.jar); " + how, List.of("-Djpf.home=" + partial.getParent()), null);
        // every file there, jpf.jar cut short
        Files.write(partial.resolve("jpf-classes.jar"), emptyJar);
        Files.writeString(partial.resolveSibling("site.properties"), "");
        Files.write(partial.resolve("jpf.jar"), new byte[] {'P', 'K', 3, 4, 0, 0});
        assertJpfMissing(2, "jmclbench: verify: -Djpf.home=" + partial.getParent() + ": no Java PathFinder build there"
                + " (build/jpf.jar is not a whole jar); " + how, List.of("-Djpf.home=" + partial.getParent()), null);
        String home = System.getProperty("jpf.home");
        Assumptions.assumeTrue(home != null && Files.isRegularFile(Path.of(home, "build/jpf-classes.jar")), "no JPF build here for the -Djpf.java case");
        assertJpfMissing(2, "jmclbench: verify: -Djpf.java=" + nowhere + ": no such executable java",
                List.of("-Djpf.home=" + home, "-Djpf.java=" + nowhere), null);
    }

    /**
     * Outside the launcher, with no jpf.home and no JPF_HOME, the default build missing: one line
     * saying how to get one, exit 1 (nothing the user gave is wrong), no results file.
     */
    @Test
    void noJpfBuildAtTheDefaultPlaceIsOneLine() throws Exception {
        Path user = Files.createDirectories(dir.resolve("user"));
        assertJpfMissing(1, "jmclbench: verify: no Java PathFinder build at " + user.resolve(".cache/jmclbench/jpf/current")
                + " (no such folder): verification/build-jpf.sh builds one (JPF_CORE_SRC: a jpf-core folder or tarball"
                + " such as jpf-core-7ea25de.tar.gz; ./jmclbench verify runs it), or set -Djpf.home / JPF_HOME to one",
                List.of("-Duser.home=" + user), null);
    }

    /** Runs verify on one JPF check with its results file given, without the test's jpf.home, and expects {@code message} alone. */
    private void assertJpfMissing(int exit, String message, List<String> props, String jpfHomeEnv) throws Exception {
        Path out = dir.resolve("out.txt");
        Path err = dir.resolve("err.txt");
        List<String> cmd = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "-cp", System.getProperty("java.class.path")));
        cmd.addAll(props);
        cmd.addAll(List.of(VerifyMain.class.getName(), "--only", "mission-seeded-stray-allocation", "--out",
                "results/verification.json"));
        ProcessBuilder pb = new ProcessBuilder(cmd).directory(dir.toFile()).redirectOutput(out.toFile())
                .redirectError(err.toFile());
        pb.environment().remove("JPF_HOME");
        if (jpfHomeEnv != null) {
            pb.environment().put("JPF_HOME", jpfHomeEnv);
        }
        Process p = pb.start();
        if (!p.waitFor(120, TimeUnit.SECONDS)) {
            p.descendants().forEach(ProcessHandle::destroyForcibly);
            p.destroyForcibly();
            throw new AssertionError("verify did not end");
        }
        assertEquals(exit, p.exitValue(), Files.readString(err));
        assertEquals(List.of(message), Files.readAllLines(err, StandardCharsets.UTF_8));
        assertEquals("", Files.readString(out), "nothing on stdout: no table header before the error");
        assertFalse(Files.exists(dir.resolve("results/verification.json")), "no results file without JPF");
    }

    private void assertBadInput(String message, String... args) throws Exception {
        Path out = dir.resolve("out.txt");
        Path err = dir.resolve("err.txt");
        List<String> cmd = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "-cp", System.getProperty("java.class.path")));
        String jpfHome = System.getProperty("jpf.home");
        if (jpfHome != null && !jpfHome.isBlank()) {
            cmd.add("-Djpf.home=" + jpfHome); // as the launcher gives it
        }
        cmd.add(VerifyMain.class.getName());
        cmd.addAll(List.of(args));
        Process p = new ProcessBuilder(cmd).directory(dir.toFile()).redirectOutput(out.toFile())
                .redirectError(err.toFile()).start();
        if (!p.waitFor(120, TimeUnit.SECONDS)) {
            // a whole verify taken for bad input: do not leave it (and its JPF JVMs) running
            p.descendants().forEach(ProcessHandle::destroyForcibly);
            p.destroyForcibly();
            throw new AssertionError("verify did not end");
        }
        assertEquals(2, p.exitValue(), Files.readString(err));
        assertEquals(List.of(message), Files.readAllLines(err, StandardCharsets.UTF_8));
        assertEquals("", Files.readString(out), "nothing on stdout: no table header before the error");
        assertFalse(new File(dir.toFile(), "results").exists(), "no verification.json for bad input");
    }
}
