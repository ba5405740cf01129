package org.jmclbench.hvm.launcher;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.File;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.stream.Stream;

import org.jmclbench.workload.WorkloadMain;
import org.jmclbench.workload.testing.SyntheticDataset;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * An HVM executable that crashes, hangs, or reports an SCJ memory area full, is that run's failure: exit 1,
 * one line (the area named), no summary.json. A stand-in for hvm/build-mission.sh hands the run an
 * executable that does so, so these need no HVM tool chain (HvmRunTest overflows a real one).
 */
class HvmFailureTest {

    @TempDir
    File tmp;

    private final String home = System.getProperty("jmclbench.home");
    private final ByteArrayOutputStream err = new ByteArrayOutputStream();

    @AfterEach
    void restoreHome() {
        if (home == null) {
            System.clearProperty("jmclbench.home");
        } else {
            System.setProperty("jmclbench.home", home);
        }
    }

    /** A home whose hvm/build-mission.sh "builds" an executable running {@code body}. */
    private void homeWithExecutable(String body) throws IOException {
        Path h = tmp.toPath().resolve("home");
        Path exe = h.resolve("fake-hvm");
        Path build = h.resolve("hvm/build-mission.sh");
        Files.createDirectories(build.getParent());
        write(exe, "#!/usr/bin/env bash\necho 'HVM: starting the mission'\n" + body + "\n");
        write(build, "#!/usr/bin/env bash\necho '" + exe + "'\n");
        for (Path p : new Path[] {exe, build}) {
            Files.setPosixFilePermissions(p, PosixFilePermissions.fromString("rwxr-xr-x"));
        }
        System.setProperty("jmclbench.home", h.toString());
    }

    private static void write(Path p, String text) throws IOException {
        Files.write(p, text.getBytes(StandardCharsets.UTF_8));
    }

    private int run(String... extra) throws IOException {
        File ds = SyntheticDataset.write(new File(tmp, "ds"), 2.0, 3, true, true);
        String[] args = Stream.concat(Stream.of("run", "--engine", "hvm", "-p", "100", "--dataset", ds.getPath(),
                "-O", new File(tmp, "out").getPath()), Stream.of(extra)).toArray(String[]::new);
        err.reset();
        return WorkloadMain.run(args, new PrintStream(new ByteArrayOutputStream()), new PrintStream(err, true, "UTF-8"));
    }

    private String err() {
        return new String(err.toByteArray(), StandardCharsets.UTF_8);
    }

    /** The run's failure: one line on stderr starting with {@code message}, and nothing recorded as valid. */
    private void assertFailedWith(String message) throws IOException {
        assertTrue(err().startsWith(message), err());
        assertEquals(1, err().trim().split("\n").length, err());
        try (Stream<Path> s = Files.walk(tmp.toPath().resolve("out"))) {
            assertFalse(s.anyMatch(p -> p.getFileName().toString().equals("summary.json")), "nothing recorded as valid");
        }
    }

    @Test
    void aCrashingExecutableIsTheRunsFailure() throws Exception {
        homeWithExecutable("kill -SEGV $$");
        assertEquals(1, run(), err());
        assertFailedWith("jmclbench: failure: the HVM executable failed (exit status 139)");
    }

    @Test
    void aHangingExecutableIsKilledAndTheRunsFailure() throws Exception {
        homeWithExecutable("exec sleep 60");
        System.setProperty(HvmRun.TIMEOUT_MARGIN_PROPERTY, "1");
        try {
            long started = System.nanoTime();
            assertEquals(1, run("--time-scale", "0.01"), err());
            assertTrue(System.nanoTime() - started < 50e9, "killed at its timeout, not waited for");
        } finally {
            System.clearProperty(HvmRun.TIMEOUT_MARGIN_PROPERTY);
        }
        // 4 x the replay (2 s x 0.01) rounded up, plus the 1 s margin
        assertFailedWith("jmclbench: failure: the HVM executable did not end within 2 s (hung); log: ");
    }

    @Test
    void aCountPastTheHvmsArraysIsUnsupportedBeforeAnythingIsBuiltOrStarted() throws Exception {
        homeWithExecutable("touch '" + tmp + "/started'");
        Path build = tmp.toPath().resolve("home/hvm/build-mission.sh");
        write(build, "#!/usr/bin/env bash\ntouch '" + tmp + "/built'\nexit 1\n");
        for (String[] past : new String[][] {{"-p", "65536"}, {"-p", "8192", "--memory", "scoped"}}) {
            assertEquals(WorkloadMain.UNSUPPORTED, run(past), err());
            assertTrue(err().startsWith("jmclbench: unsupported: --particles " + past[1] + ": the HVM "), err());
            assertEquals(1, err().trim().split("\n").length, err());
        }
        assertNothingBuiltStartedOrBegun();
    }

    @Test
    void aBadHvmSrcIsBadInputBeforeAnythingIsBuiltOrBegun() throws Exception {
        // it was build-hvm.sh's line, then "failure: cannot build the HVM executable", exit 1, and
        // the run folder's parents left behind
        homeWithExecutable("touch '" + tmp + "/started'");
        Path h = tmp.toPath().resolve("home/hvm");
        write(h.resolve("build-mission.sh"), "#!/usr/bin/env bash\ntouch '" + tmp + "/built'\nexit 2\n");
        write(h.resolve("build-hvm.sh"), "#!/usr/bin/env bash\n[ \"$1\" = --check ] || touch '" + tmp + "/built'\n"
                + "echo 'build-hvm: HVM_SRC=/no/such.tar.gz: no such file or folder' >&2\nexit 2\n");
        Files.setPosixFilePermissions(h.resolve("build-hvm.sh"), PosixFilePermissions.fromString("rwxr-xr-x"));
        assertEquals(WorkloadMain.BAD_INPUT, run(), err());
        assertEquals("jmclbench: HVM_SRC=/no/such.tar.gz: no such file or folder\n", err());
        assertNothingBuiltStartedOrBegun();
    }

    @Test
    void optionsTheHvmRunIgnoresAreBadInputBeforeAnythingIsBuilt() throws Exception {
        // each ran, and summary.json recorded it among the run's parameters
        homeWithExecutable("touch '" + tmp + "/started'");
        String[][] cases = {{"--warmup", "2", "jmclbench: --warmup: the hvm engine has no warm-up"},
                {"--spin-us", "100", "jmclbench: --spin-us: the hvm engine releases on the HVM's own clock tick"},
                {"--gc-log", null, "jmclbench: --gc-log: the hvm engine has no GC log"}};
        for (String[] c : cases) {
            assertEquals(WorkloadMain.BAD_INPUT, c[1] == null ? run(c[0]) : run(c[0], c[1]), err());
            assertTrue(err().startsWith(c[2]), err());
            assertEquals(1, err().trim().split("\n").length, err());
        }
        assertNothingBuiltStartedOrBegun();
    }

    /** Refused before the executable is built or started, and before the run folder is begun. */
    private void assertNothingBuiltStartedOrBegun() {
        assertFalse(new File(tmp, "built").exists(), "refused before the executable is built");
        assertFalse(new File(tmp, "started").exists(), "the executable was started");
        assertFalse(new File(tmp, "out").exists(), "no run folder begun");
    }

    @Test
    void aFloodedLogIsReadAtItsEndsOnly() throws Exception {
        // hvm.log was read whole: 3 GB of output (here a sparse file) ended the run's JVM with
        // "Required array size too large" instead of the run's one line
        String flood = "truncate -s 3G /dev/stdout\nexec >> \"$(readlink /proc/$$/fd/1)\"\n";
        homeWithExecutable(flood + "echo 'out of memory: 0x7d0, 0x1f40'\nexit 1");
        assertEquals(1, run("--memory", "scoped", "--area-size", "update=2000"), err());
        assertFailedWith("jmclbench: failure: memory area 'update' overflowed on the HVM");

        homeWithExecutable(flood + "echo 'the last words'\nkill -SEGV $$");
        assertEquals(1, run(), err());
        assertFailedWith("jmclbench: failure: the HVM executable failed (exit status 139): ");
        assertTrue(err().contains("the last words (log: "), err());
    }

    @Test
    void aCrashQuotesTheLastLinesThatSaySomething() throws Exception {
        // a log written past a hole holds a line of NULs: it was quoted as an empty " |  | " segment
        homeWithExecutable("echo 'mission: predict released'\nprintf '\\0\\0\\0\\n\\n   \\n'\necho 'the last words'\nkill -SEGV $$");
        assertEquals(1, run(), err());
        assertFailedWith("jmclbench: failure: the HVM executable failed (exit status 139): HVM: starting the mission"
                + " | mission: predict released | the last words (log: ");
    }

    @Test
    void aFullMemoryAreaIsNamedAndTheRunsFailure() throws Exception {
        // icecap's words when an allocation does not fit: the area's size and the request, in hex (2000 = 0x7d0)
        homeWithExecutable("echo 'out of memory: 0x7d0, 0x1f40'\nexit 1");
        assertEquals(1, run("--memory", "scoped", "--area-size", "update=2000"), err());
        assertFailedWith("jmclbench: failure: memory area 'update' overflowed on the HVM: an allocation of 8000"
                + " bytes did not fit its 2000 bytes");
    }
}
