package org.jmclbench.verification.jpf;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * build-jpf.sh without JPF_CORE_SRC: a build of the pinned commit's own sources in the cache is
 * used as it is; anything else would be a clone (here a git that fails, as with no network).
 */
class BuildJpfScriptTest {
    private static final Path SCRIPT = Paths.get("build-jpf.sh").toAbsolutePath();
    private static final String PINNED = "7ea25de453111be77d09e12eb196fecf2dc6d365";

    @TempDir
    Path dir;

    @Test
    void aBuildOfThePinnedCommitIsUsedWithoutCloning() throws Exception {
        Path home = fakeHome("7ea25de-0123456789ab");
        Files.writeString(home.resolve("PINNED"), PINNED + " patches " + patchHash() + "\n");
        Result r = run();
        assertEquals(0, r.exit, r.err);
        assertEquals(home.toString(), r.out.strip());
        assertFalse(r.err.contains("cloning"), r.err);
        assertEquals(home.toRealPath(), dir.resolve("cache/jpf/current").toRealPath());
    }

    @Test
    void aBuildOfOtherSourcesIsNotTakenForThePinnedCommit() throws Exception {
        fakeHome("7ea25de-0123456789ab"); // from a JPF_CORE_SRC folder at that commit, perhaps edited: no PINNED
        Result r = run();
        assertEquals(3, r.exit, r.out);
        assertEquals(NO_SOURCE, r.err);
    }

    /** What build-jpf.sh says, alone, when it has no source and its clone fails (the stand-in git's line in it). */
    private static final String NO_SOURCE = "build-jpf: no Java PathFinder: JPF_CORE_SRC is not set and"
            + " https://github.com/javapathfinder/jpf-core cannot be cloned (fatal: unable to access (no network in this test));"
            + " set JPF_CORE_SRC to a jpf-core folder or tarball (jpf-core-7ea25de.tar.gz)\n";

    /**
     * No JPF_CORE_SRC, no build in the cache and no network: one line saying how to get the source, and
     * ./jmclbench verify ends with it alone, exit 1 (nothing the user gave is wrong). It was four lines:
     * "cloning", git's, "cannot clone", and the launcher's own "cannot build Java PathFinder".
     */
    @Test
    void noSourceAndNoCloneIsOneLineAndTheLauncherAddsNone() throws Exception {
        Result r = run();
        assertEquals(3, r.exit, r.err);
        assertEquals(NO_SOURCE, r.err);
        assertEquals("", r.out);
        r = run(null, SCRIPT.getParent().getParent().resolve("jmclbench").toString(), "verify", "--help");
        assertEquals(1, r.exit, r.err);
        assertEquals(NO_SOURCE, r.err);
    }

    /**
     * A build of the pinned commit whose jars were cut short (a full disk, a copy killed midway) is no
     * build: it was used, and Maven's compile of verification failed on it in some 400 lines.
     */
    @Test
    void aDamagedBuildOfThePinnedCommitIsNotUsed() throws Exception {
        Path home = fakeHome("7ea25de-0123456789ab");
        Files.writeString(home.resolve("PINNED"), PINNED + " patches " + patchHash() + "\n");
        Files.write(home.resolve("build/jpf.jar"), new byte[] {'P', 'K', 3, 4, 0, 0}); // a jar's start, no end
        Result r = run();
        assertEquals(3, r.exit, r.err);
        assertEquals(NO_SOURCE.replace("is not set and", "is not set, the build at " + home + " is damaged, and"), r.err);
    }

    @Test
    void aBuildOfThePinnedCommitWithoutOurPatchesIsNotUsed() throws Exception {
        // a build made before jpf-patches/ (its model Thread has no onSpinWait) was taken as it was
        Path home = fakeHome("7ea25de-0123456789ab");
        Files.writeString(home.resolve("PINNED"), PINNED + "\n");
        Result r = run();
        assertEquals(3, r.exit, r.out);
        assertEquals(NO_SOURCE, r.err);
    }

    /** What build-jpf.sh marks a build with: the first 12 hex digits of the SHA-256 of jpf-patches/*.patch, in name order. */
    private static String patchHash() throws Exception {
        java.security.MessageDigest md = java.security.MessageDigest.getInstance("SHA-256");
        try (java.util.stream.Stream<Path> s = Files.list(SCRIPT.getParent().resolve("jpf-patches"))) {
            for (Path p : s.filter(f -> f.toString().endsWith(".patch")).sorted().toList()) {
                md.update(Files.readAllBytes(p));
            }
        }
        return java.util.HexFormat.of().formatHex(md.digest()).substring(0, 12);
    }

    @Test
    void helpPrintsTheHeader() throws Exception {
        // --help was an unknown option, exit 2
        Result r = run(null, "--help");
        assertEquals(0, r.exit, r.err);
        assertTrue(r.out.startsWith("Builds Java PathFinder"), r.out);
        assertTrue(r.out.contains("Usage: build-jpf.sh [--quiet] [--link PATH]"), r.out);
    }

    @Test
    void aJpfCoreSrcThatIsNoJpfCoreIsOneLineAndExit2() throws Exception {
        // each was exit 1, and a file that is not a tarball printed gzip's and tar's lines first
        Path notTar = dir.resolve("jpf.tar.gz");
        Files.writeString(notTar, "not a tarball");
        Path empty = Files.createDirectories(dir.resolve("empty"));
        Path missing = dir.resolve("missing.tar.gz");
        String[][] cases = {{missing.toString(), "no such folder or file"}, {notTar.toString(), "not a readable .tar.gz"},
                {empty.toString(), "not a jpf-core tree (no src/main)"}};
        for (String[] c : cases) {
            String line = "build-jpf: JPF_CORE_SRC=" + c[0] + ": " + c[1] + "\n";
            Result r = run(c[0]);
            assertEquals(2, r.exit, r.err);
            assertEquals(line, r.err);
            assertEquals("", r.out);
            // and ./jmclbench verify passes it on, without a line of its own (it added "cannot build
            // Java PathFinder" and exit 1)
            r = run(c[0], SCRIPT.getParent().getParent().resolve("jmclbench").toString(), "verify", "--help");
            assertEquals(2, r.exit, r.err);
            assertEquals(line, r.err);
        }
    }

    private Path fakeHome(String key) throws IOException {
        Path home = dir.resolve("cache/jpf").resolve(key);
        Files.createDirectories(home.resolve("build"));
        for (String f : new String[] {"build/jpf.jar", "build/jpf-classes.jar"}) {
            Files.write(home.resolve(f), EMPTY_JAR);
        }
        Files.writeString(home.resolve("site.properties"), "");
        return home;
    }

    /** A whole jar with nothing in it: the zip end record alone. */
    private static final byte[] EMPTY_JAR = {'P', 'K', 5, 6, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0};

    private record Result(int exit, String out, String err) {
    }

    private Result run() throws Exception {
        return run(null);
    }

    /** build-jpf.sh with {@code JPF_CORE_SRC} (none when null) and {@code args}; a first arg naming a file runs that instead. */
    private Result run(String jpfCoreSrc, String... args) throws Exception {
        Path bin = Files.createDirectories(dir.resolve("bin"));
        Path git = bin.resolve("git");
        Files.writeString(git, "#!/bin/sh\necho 'fatal: unable to access (no network in this test)' >&2\nexit 128\n");
        Files.setPosixFilePermissions(git, PosixFilePermissions.fromString("rwxr-xr-x"));
        List<String> cmd = new ArrayList<>();
        if (args.length > 0 && args[0].startsWith("/")) {
            cmd.addAll(List.of(args));
        } else {
            cmd.addAll(List.of("bash", SCRIPT.toString()));
            cmd.addAll(List.of(args));
        }
        ProcessBuilder pb = new ProcessBuilder(cmd);
        pb.environment().remove("JPF_CORE_SRC");
        if (jpfCoreSrc != null) {
            pb.environment().put("JPF_CORE_SRC", jpfCoreSrc);
        }
        pb.environment().put("JMCLBENCH_CACHE", dir.resolve("cache").toString());
        pb.environment().put("PATH", bin + ":" + System.getenv("PATH"));
        Path out = dir.resolve("out.txt");
        Path err = dir.resolve("err.txt");
        Process p = pb.redirectOutput(out.toFile()).redirectError(err.toFile()).start();
        assertTrue(p.waitFor(60, TimeUnit.SECONDS), "build-jpf.sh did not end");
        return new Result(p.exitValue(), Files.readString(out), Files.readString(err));
    }
}
