package org.jmclbench.tooling.generator;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import org.jmclbench.tooling.Fixtures;
import org.jmclbench.tooling.Fixtures.CliResult;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class GenerateCommandTest {
    @TempDir
    Path tmp;

    private static CliResult generate(String... args) {
        String[] full = new String[args.length + 1];
        full[0] = "generate";
        System.arraycopy(args, 0, full, 1, args.length);
        return Fixtures.cli(full);
    }

    private static void assertBadUsage(CliResult r, String mentions) {
        assertEquals(2, r.exitCode(), r.err());
        assertTrue(r.err().startsWith("jmclbench: "), r.err());
        assertEquals(1, r.err().lines().count(), "one line: " + r.err());
        assertTrue(r.err().contains(mentions), r.err());
    }

    @Test
    void writesADatasetAndTheSameAgainForTheSameSeed() throws Exception {
        Path a = tmp.resolve("a");
        Path b = tmp.resolve("b");
        assertEquals(0, generate("--scenario", "stay", "--seed", "3", "--duration", "2", "--out", a.toString()).exitCode());
        assertEquals(0, generate("--scenario", "stay", "--seed", "3", "--duration", "2", "--out", b.toString()).exitCode());
        for (String f : DatasetWriter.FILES) {
            assertArrayEquals(Files.readAllBytes(a.resolve(f)), Files.readAllBytes(b.resolve(f)), f);
        }
        assertEquals(40, Files.readAllLines(a.resolve("odometry.txt")).size());
        String props = Files.readString(a.resolve("dataset.properties"));
        assertTrue(props.contains("\nseed=3\n") && props.contains("\nduration=2.0\n"), props);
        // Nothing but the two datasets: no temporary folder left behind.
        try (var entries = Files.list(tmp)) {
            assertEquals(List.of("a", "b"), entries.map(p -> p.getFileName().toString()).sorted().toList());
        }
    }

    @Test
    void badOptionsAreOneLineAndExitCode2() {
        String out = tmp.resolve("x").toString();
        assertBadUsage(generate("--scenario", "nowhere", "--out", out), "--scenario");
        assertBadUsage(generate("--scenario", "match", "--out", out, "--duration", "0.03"), "--duration");
        assertBadUsage(generate("--scenario", "match", "--out", out, "--duration", "-1"), "--duration");
        assertBadUsage(generate("--scenario", "match", "--out", out, "--duration", "NaN"), "--duration");
        assertBadUsage(generate("--scenario", "match", "--out", out, "--duration", "abc"), "--duration");
        assertBadUsage(generate("--scenario", "match", "--out", out, "--seed", "1.5"), "--seed");
        assertBadUsage(generate("--scenario", "match"), "--out");
        assertBadUsage(generate("--out", out), "--scenario");
        assertBadUsage(generate("--scenario", "match", "--out", out, "--colour", "red"), "--colour");
        assertFalse(Files.exists(tmp.resolve("x")), "nothing written after bad usage");
    }

    @Test
    void aDurationTooShortForALaserEventIsRefusedNotWritten() {
        // 0.05 s: one odometry reading and no beam crossing; the workload rejects an empty laser.txt.
        Path out = tmp.resolve("short");
        assertBadUsage(generate("--scenario", "match", "--duration", "0.05", "--out", out.toString()), "--duration");
        assertFalse(Files.exists(out), "no dataset the workload cannot read");
    }

    @Test
    void aKidnapPastTheEndOfTheDataIsNotInTheMetadata() throws Exception {
        // the data end at 20 s, before the kidnapping at 30 s: there is none to describe
        Path shortRun = tmp.resolve("short");
        assertEquals(0, generate("--scenario", "kidnap", "--duration", "20", "--out", shortRun.toString()).exitCode());
        String props = Files.readString(shortRun.resolve("dataset.properties"));
        assertFalse(props.contains("kidnap."), props);
        Path longRun = tmp.resolve("long");
        assertEquals(0, generate("--scenario", "kidnap", "--duration", "31", "--out", longRun.toString()).exitCode());
        assertTrue(Files.readString(longRun.resolve("dataset.properties")).contains("\nkidnap.time=30.0\n"));
    }

    @Test
    void theDatasetFolderGetsTheUsualPermissions() throws Exception {
        // others run the workload on it: not the owner-only folder a temporary directory is
        Path usual = Files.createDirectory(tmp.resolve("usual"));
        Path dir = tmp.resolve("dataset");
        assertEquals(0, generate("--scenario", "stay", "--duration", "1", "--out", dir.toString()).exitCode());
        assertEquals(Files.getPosixFilePermissions(usual), Files.getPosixFilePermissions(dir));
    }

    @Test
    void helpExitsZero() {
        CliResult r = generate("--help");
        assertEquals(0, r.exitCode());
        assertTrue(r.out().contains("--scenario") && r.out().contains("figure8"), r.out());
    }

    @Test
    void refusesToOverwriteWithoutForce() throws Exception {
        Path dir = tmp.resolve("d");
        assertEquals(0, generate("--scenario", "stay", "--duration", "1", "--out", dir.toString()).exitCode());
        byte[] before = Files.readAllBytes(dir.resolve("odometry.txt"));
        assertBadUsage(generate("--scenario", "stay", "--seed", "2", "--duration", "1", "--out", dir.toString()), "--force");
        assertArrayEquals(before, Files.readAllBytes(dir.resolve("odometry.txt")));
        assertEquals(0, generate("--scenario", "stay", "--seed", "2", "--duration", "1", "--out", dir.toString(), "--force")
                .exitCode());
        assertFalse(java.util.Arrays.equals(before, Files.readAllBytes(dir.resolve("odometry.txt"))));
    }

    @Test
    void forceDoesNotDeleteAFolderThatIsNotADataset() throws Exception {
        Path dir = tmp.resolve("home");
        Files.createDirectories(dir);
        Files.writeString(dir.resolve("thesis.tex"), "precious");
        assertBadUsage(generate("--scenario", "stay", "--duration", "1", "--out", dir.toString(), "--force"), "--out");
        assertEquals("precious", Files.readString(dir.resolve("thesis.tex")));
        assertFalse(Files.exists(dir.resolve("odometry.txt")));
    }

    @Test
    void unwritablePlaceIsOneLineAndExitCode2() throws Exception {
        Path file = tmp.resolve("plain-file");
        Files.writeString(file, "x");
        assertBadUsage(generate("--scenario", "stay", "--duration", "1", "--out", file.resolve("sub").toString()), "--out");
        assertBadUsage(generate("--scenario", "stay", "--duration", "1", "--out", file.toString()), "--out");
    }

    @Test
    void theWorkingFolderIsNotADatasetFolder() throws Exception {
        // '.' (or an empty --out, now refused as every empty path is) named the working folder: when it was
        // empty, the write replaced it by a new folder, leaving the caller's shell in a deleted one (a child
        // JVM: this one's folder is not empty)
        Path cwd = Files.createDirectories(tmp.resolve("cwd"));
        Object before = Files.readAttributes(cwd, java.nio.file.attribute.BasicFileAttributes.class).fileKey();
        for (String out : new String[] {".", "sub/.."}) {
            Process p = new ProcessBuilder(Fixtures.childCli(tmp, "generate", "--scenario", "stay", "--duration", "1",
                    "--out", out)).directory(cwd.toFile()).redirectOutput(ProcessBuilder.Redirect.DISCARD).start();
            String err = new String(p.getErrorStream().readAllBytes(), java.nio.charset.StandardCharsets.UTF_8);
            assertEquals(2, p.waitFor(), err);
            assertEquals("jmclbench: --out: '" + out + "' is the working folder; name the dataset's folder (e.g. data/NAME)",
                    err.strip());
        }
        assertEquals(before, Files.readAttributes(cwd, java.nio.file.attribute.BasicFileAttributes.class).fileKey());
        try (var entries = Files.list(cwd)) {
            assertEquals(0, entries.count());
        }
    }

    @Test
    void writesIntoAnEmptyExistingFolder() throws Exception {
        Path dir = tmp.resolve("empty");
        Files.createDirectories(dir);
        assertEquals(0, generate("--scenario", "figure8", "--duration", "1", "--out", dir.toString()).exitCode());
        assertTrue(Files.isRegularFile(dir.resolve("laser.txt")));
    }

    @Test
    void noNoiseWritesPerfectSensors() throws Exception {
        Path dir = tmp.resolve("clean");
        assertEquals(0, generate("--scenario", "match", "--duration", "5", "--no-noise", "--out", dir.toString()).exitCode());
        String props = Files.readString(dir.resolve("dataset.properties"));
        assertTrue(props.contains("\nlaser.noise=0.0\n") && props.contains("\nlaser.missProbability=0.0\n"), props);
    }
}
