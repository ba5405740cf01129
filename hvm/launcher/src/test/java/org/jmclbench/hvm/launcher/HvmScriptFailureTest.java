package org.jmclbench.hvm.launcher;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.File;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.HashMap;
import java.util.Map;

import org.jmclbench.hvm.launcher.HvmScripts.Result;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The hvm/*.sh scripts' failures (not bad input): a step that fails ends the script with one line
 * naming what failed, exit 1, and nothing left in the cache. Stand-in tools on PATH fail as the
 * real ones do without network, so none of these needs the network or the tool chain.
 */
class HvmScriptFailureTest {
    private static final String REPO = "https://github.com/scj-devel/hvm-scj";
    private static final String COMMIT = "4d31e231688a7fdaddd464d21a3923b435d11683";

    @TempDir
    Path dir;
    private HvmScripts scripts;
    private Path bin;

    @BeforeEach
    void toolsThatAreNeverReached() throws Exception {
        // build-hvm.sh only asks whether these exist before it fetches the source; each stand-in
        // fails loudly, should it be run
        Assumptions.assumeTrue("Linux".equals(System.getProperty("os.name")) && "amd64".equals(System.getProperty("os.arch")),
                "build-hvm.sh builds on x86_64 Linux only");
        scripts = new HvmScripts(dir);
        bin = Files.createDirectory(dir.resolve("bin"));
        for (String tool : new String[] {"javac", "java", "gcc", "mvn", "patch", "pip3"}) {
            tool(tool, "echo 'a stand-in that should not have run: " + tool + "' >&2; exit 97");
        }
    }

    private void tool(String name, String body) throws Exception {
        Path p = bin.resolve(name);
        Files.write(p, ("#!/bin/sh\n" + body + "\n").getBytes(StandardCharsets.UTF_8));
        Files.setPosixFilePermissions(p, PosixFilePermissions.fromString("rwxr-xr-x"));
    }

    /** build-hvm.sh without HVM_SRC (so it clones), the stand-ins first on PATH. */
    private Result buildFromAClone() throws Exception {
        return scripts.run(cloningEnvironment(), "build-hvm.sh");
    }

    /** No HVM_SRC (so build-hvm.sh clones) and no JAVA8_HOME; the stand-ins first on PATH. */
    private Map<String, String> cloningEnvironment() {
        Map<String, String> env = new HashMap<>();
        env.put("HVM_SRC", null);
        env.put("JAVA8_HOME", null);
        env.put("PATH", bin + File.pathSeparator + System.getenv("PATH"));
        return env;
    }

    @Test
    void aFailedCloneIsOneLineNamingTheRepository() throws Exception {
        // it went on past the failed clone (set -e does not stop `clone && checkout`) to
        // "no icecapvm/src in the HVM source"
        tool("git", "echo \"fatal: unable to access '" + REPO + "/': Could not resolve host: github.com\" >&2; exit 128");
        assertFailed(buildFromAClone(), "build-hvm: cannot clone " + REPO + ": fatal: unable to access '" + REPO
                + "/': Could not resolve host: github.com");
    }

    @Test
    void aFailedCheckoutIsOneLineNamingTheCommit() throws Exception {
        // it ended with git's exit status 128 and git's words only
        tool("git", "if [ \"$1\" = clone ]; then mkdir -p \"$4\"; exit 0; fi\n"
                + "echo 'fatal: reference is not a tree: " + COMMIT + "' >&2; exit 128");
        assertFailed(buildFromAClone(), "build-hvm: cannot check out commit " + COMMIT + " of " + REPO
                + ": fatal: reference is not a tree: " + COMMIT);
    }

    @Test
    void theScriptsThatBuildTheToolChainFailWithItsLine() throws Exception {
        tool("git", "echo 'fatal: unable to access: Could not resolve host: github.com' >&2; exit 128");
        for (String script : new String[] {"build-mission.sh", "difftest.sh", "test-patches.sh", "upstream-scj-tests.sh"}) {
            Result r = scripts.run(cloningEnvironment(), script);
            assertEquals(1, r.exit, script + ": " + r.err);
            assertTrue(r.err.endsWith("\nbuild-hvm: cannot clone " + REPO + ": fatal: unable to access: Could not resolve host:"
                    + " github.com\n"), script + ": " + r.err);
        }
    }

    @Test
    void aGeneratedProgramThatDoesNotCompileIsAFailureNotBadUsage() throws Exception {
        // it was exit 2, as if an option had been wrong; here the tool chain has no class library
        Path chain = Files.createDirectory(dir.resolve("chain"));
        Files.write(chain.resolve("KEY"), "source test\n".getBytes(StandardCharsets.UTF_8));
        Result r = scripts.run(new HashMap<>(), "difftest.sh", "--toolchain", chain.toString(), "--seeds", "1", "--count", "2");
        assertEquals(1, r.exit, r.err);
        assertTrue(r.err.trim().matches("(?s).*\ndifftest: the generated program \\S+/G1\\.java does not compile against "
                + chain.toRealPath() + " \\(gen.py's bug, or the tool chain's\\)"), r.err);
    }

    @Test
    void aMissingToolIsOneLineAndExit1BeforeAnythingRuns() throws Exception {
        // bash's "command not found" mid-way, exit 127 (difftest.sh after compiling its runner,
        // test-patches.sh after building the tool chain)
        Path chain = Files.createDirectory(dir.resolve("chain"));
        Files.write(chain.resolve("KEY"), "source test\n".getBytes(StandardCharsets.UTF_8));
        Path few = Files.createDirectory(dir.resolve("few"));
        for (String tool : new String[] {"bash", "dirname", "readlink", "basename", "realpath", "seq"}) {
            Files.createSymbolicLink(few.resolve(tool), onPath(tool));
        }
        Map<String, String> env = new HashMap<>();
        env.put("PATH", few.toString());
        String[][] cases = {{"difftest.sh", "python3 java javac timeout", "--toolchain", chain.toString()},
                {"hvmc.sh", "java gcc", "--toolchain", chain.toString(), "--classes", ".", "--main", "a.B", "-o", "exe"},
                {"build-mission.sh", "javac"}, {"test-patches.sh", "javac timeout"}, {"upstream-scj-tests.sh", "javac timeout"}};
        for (String[] c : cases) {
            Result r = scripts.run(env, c[0], java.util.Arrays.copyOfRange(c, 2, c.length));
            assertEquals(1, r.exit, c[0] + ": " + r.err);
            assertEquals(c[0].replace(".sh", "") + ": not installed: " + c[1] + "\n", r.err, c[0]);
        }
    }

    private static Path onPath(String tool) {
        for (String d : System.getenv("PATH").split(File.pathSeparator)) {
            Path p = java.nio.file.Paths.get(d, tool);
            if (Files.isExecutable(p)) {
                return p;
            }
        }
        throw new AssertionError(tool + " is not on PATH");
    }

    @Test
    void aFailedCompilerNamesNoLogItRemoves() throws Exception {
        // it named the temporary log, which the script removed as it ended
        Path chain = Files.createDirectory(dir.resolve("chain"));
        Files.write(chain.resolve("KEY"), "source test\n".getBytes(StandardCharsets.UTF_8));
        Result r = scripts.run(new HashMap<>(), "hvmc.sh", "--toolchain", chain.toString(), "--classes", ".", "--main", "a.B",
                "-o", "exe");
        assertEquals(1, r.exit, r.err);
        assertTrue(r.err.startsWith("hvmc: the icecap compiler failed for a.B (no log kept: --log FILE keeps it):\n"), r.err);
        Path log = dir.resolve("logs/c.log");
        r = scripts.run(new HashMap<>(), "hvmc.sh", "--toolchain", chain.toString(), "--classes", ".", "--main", "a.B",
                "-o", "exe", "--log", log.toString());
        assertTrue(r.err.startsWith("hvmc: the icecap compiler failed for a.B (log: " + log + "):\n"), r.err);
        assertTrue(Files.isRegularFile(log), "the named log is there");
    }

    /** Exit 1, {@code line} the one line of error after the progress line, no output, nothing left in the cache. */
    private void assertFailed(Result r, String line) {
        assertEquals(1, r.exit, r.err);
        assertEquals("build-hvm: unpacking the icecap sources (git)\n" + line + "\n", r.err);
        assertEquals("", r.out);
        String[] left = dir.resolve("cache/hvm").toFile().list();
        assertEquals(0, left == null ? 0 : left.length, "the cache holds nothing of the failed build");
    }
}
