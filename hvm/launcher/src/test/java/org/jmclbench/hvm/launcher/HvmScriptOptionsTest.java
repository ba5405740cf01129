package org.jmclbench.hvm.launcher;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Collections;
import java.util.List;
import java.util.Map;

import org.jmclbench.hvm.launcher.HvmScripts.Result;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The hvm/*.sh scripts' command lines: --help prints the script's header, the whole of it and
 * nothing else; a bad option, value or HVM_SRC is one line naming it and exit 2, found before
 * anything is built (none of these cases needs the tool chain).
 */
class HvmScriptOptionsTest {
    private static final List<String> SCRIPTS = Arrays.asList("build-hvm.sh", "build-mission.sh", "difftest.sh", "hvmc.sh",
            "test-patches.sh", "upstream-scj-tests.sh");

    @TempDir
    Path dir;
    private Path hvm;
    private HvmScripts scripts;

    @BeforeEach
    void findScripts() {
        scripts = new HvmScripts(dir);
        hvm = scripts.hvm();
    }

    @Test
    void helpIsTheWholeHeader() throws Exception {
        // fixed line ranges had drifted: test-patches.sh cut its usage line off, build-hvm.sh
        // printed two lines of code, hvmc.sh cut its last line off
        for (String script : SCRIPTS) {
            List<String> lines = Files.readAllLines(hvm.resolve(script), StandardCharsets.UTF_8);
            List<String> header = new ArrayList<>();
            for (String line : lines.subList(1, lines.size())) {
                if (!line.startsWith("#")) {
                    break;
                }
                header.add(line.replaceFirst("^# ?", ""));
            }
            Result r = run(Collections.emptyMap(), script, "--help");
            assertEquals(0, r.exit, script + ": " + r.err);
            assertEquals(String.join("\n", header), r.out.replaceAll("\\s+$", ""), script);
            assertTrue(r.out.contains("hvm/" + script), script + ": its help has no usage line");
            // a caller tells bad usage from a failure by the code alone
            assertTrue(r.out.matches("(?s).*\nExit codes: 0 .*;\\s+1 .*;\\s+2 bad\\s+usage .*"), script + ": its help names no exit codes");
        }
    }

    @Test
    void difftestValuesAreOneLineAndExit2() throws Exception {
        // each ran: python's traceback (--seeds x, --count -1), a failed build counted as a
        // disagreement (--modes foo), bash's "unbound variable" (a missing value), a silent exit 1
        // (--toolchain), an empty run that passed (--seeds 3-1)
        bad("difftest: --seeds: 'x' is not a range (1-5) or a list (1,7,9) of seeds", "difftest.sh", "--seeds", "x");
        bad("difftest: --seeds: 3-1 is an empty range", "difftest.sh", "--seeds", "3-1");
        bad("difftest: --seeds: needs a value", "difftest.sh", "--seeds");
        bad("difftest: --count: '-1' is not a positive number of values", "difftest.sh", "--count", "-1");
        bad("difftest: --modes: 'foo' is not a list of interpreted and compiled", "difftest.sh", "--modes", "foo");
        bad("difftest: --toolchain: /no/such/chain is not a tool chain built by build-hvm.sh",
                "difftest.sh", "--toolchain", "/no/such/chain");
        Files.write(dir.resolve("file"), bytes("x"));
        bad("difftest: --keep: file/kept: file is not a folder", "difftest.sh", "--keep", "file/kept");
        bad("difftest: unknown option: --bogus", "difftest.sh", "--bogus");
    }

    @Test
    void theOtherScriptsValuesAreOneLineAndExit2() throws Exception {
        // --only=NAME of no test ran nothing and exited 0
        String r = run(Collections.emptyMap(), "test-patches.sh", "--only=NoSuchTest").err;
        assertTrue(r.startsWith("test-patches: --only: no test named 'NoSuchTest' (one of: DoubleSubDiv "), r);
        bad(r.trim(), "test-patches.sh", "--only=NoSuchTest");
        bad("test-patches: --only: needs a test name (--only=NAME)", "test-patches.sh", "--only=");
        bad("build-mission: --heap: 'x' is not a positive number of bytes", "build-mission.sh", "--heap", "x");
        bad("build-mission: --mode: needs a value", "build-mission.sh", "--mode");
        bad("upstream-scj-tests: --timeout: '0' is not a positive number of seconds",
                "upstream-scj-tests.sh", "--timeout", "0");
        bad("upstream-scj-tests: --modes: 'hot' is not a list of interpreted and compiled",
                "upstream-scj-tests.sh", "--modes", "hot");
        bad("hvmc: -o: needs a value", "hvmc.sh", "-o");
    }

    @Test
    void hvmcPathsAreOneLineAndExit2() throws Exception {
        // -o two folders below what exists ended the script silently (exit 1, readlink -f); a
        // missing --natives file or --classes entry went on to the compiler and gcc (exit 1)
        Files.createDirectories(dir.resolve("chain"));
        Files.write(dir.resolve("chain/KEY"), bytes("source test\n"));
        bad("hvmc: /no/such/chain is not a tool chain built by build-hvm.sh",
                "hvmc.sh", "--toolchain", "/no/such/chain", "--classes", ".", "--main", "a.B", "-o", "x/y/exe");
        bad("hvmc: --natives: no such file: none.c", "hvmc.sh", "--natives", "none.c");
        bad("hvmc: --classes: no such folder or jar: none",
                "hvmc.sh", "--toolchain", "chain", "--classes", ".:none", "--main", "a.B", "-o", "exe");
    }

    @Test
    void foldersThatCannotBeWrittenAreOneLineAndExit2BeforeAnythingRuns() throws Exception {
        // hvmc.sh ran the compiler, then failed with mkdir's or mv's words (exit 1); build-hvm.sh's
        // --check said the tool chain could be built, then the build failed with mkdir's words
        Files.write(dir.resolve("file"), bytes("x"));
        Files.createDirectories(dir.resolve("chain"));
        Files.write(dir.resolve("chain/KEY"), bytes("source test\n"));
        String[] hvmc = {"--toolchain", "chain", "--classes", ".", "--main", "a.B"};
        bad("hvmc: -o: file/exe: file is not a folder", "hvmc.sh", concat(hvmc, "-o", "file/exe"));
        bad("hvmc: --log: file/x/c.log: file is not a folder", "hvmc.sh", concat(hvmc, "-o", "exe", "--log", "file/x/c.log"));
        bad("hvmc: --keep-c: file: file is not a folder", "hvmc.sh", concat(hvmc, "-o", "exe", "--keep-c", "file"));
        String cache = dir.resolve("file/cache").toString();
        Map<String, String> env = new java.util.HashMap<>();
        env.put("JMCLBENCH_CACHE", cache);
        env.put("HVM_SRC", Files.createDirectories(dir.resolve("hvm-scj/icecapvm/src")).getParent().getParent().toString());
        for (String[] args : new String[][] {{"--check"}, {}}) {
            bad(env, "build-hvm: JMCLBENCH_CACHE=" + cache + ": cannot write there (" + dir.resolve("file") + " is not a folder)",
                    "build-hvm.sh", args);
        }
    }

    private static String[] concat(String[] a, String... b) {
        String[] all = Arrays.copyOf(a, a.length + b.length);
        System.arraycopy(b, 0, all, a.length, b.length);
        return all;
    }

    @Test
    void aBadHvmSrcIsOneLineAndExit2() throws Exception {
        // a missing one was exit 1 (with --check: a lack of this machine); a file that is not a
        // tarball was gzip's and tar's four lines, then "no icecapvm/src in the HVM source"
        Path notTar = Files.write(dir.resolve("hvm.tar.gz"), bytes("not a tarball"));
        Files.createDirectory(dir.resolve("empty"));
        String missing = dir.resolve("missing.tar.gz").toString();
        for (String script : Arrays.asList("build-hvm.sh", "difftest.sh", "test-patches.sh", "build-mission.sh", "upstream-scj-tests.sh")) {
            bad(Collections.singletonMap("HVM_SRC", missing), "build-hvm: HVM_SRC=" + missing + ": no such file or folder", script);
        }
        bad(Collections.singletonMap("HVM_SRC", notTar.toString()), "build-hvm: HVM_SRC=" + notTar + ": not a gzip tarball",
                "build-hvm.sh", "--check");
        bad(Collections.singletonMap("HVM_SRC", dir.resolve("empty").toString()),
                "build-hvm: HVM_SRC=" + dir.resolve("empty") + ": not an hvm-scj folder (no icecapvm/src)",
                "build-hvm.sh", "--check");
    }

    private void bad(String line, String script, String... args) throws Exception {
        bad(Collections.emptyMap(), line, script, args);
    }

    private void bad(Map<String, String> env, String line, String script, String... args) throws Exception {
        Result r = run(env, script, args);
        assertEquals(2, r.exit, script + " " + String.join(" ", args) + ": " + r.err);
        assertEquals(line + "\n", r.err, script + " " + String.join(" ", args));
        assertEquals("", r.out, script + " " + String.join(" ", args));
    }

    private static byte[] bytes(String s) {
        return s.getBytes(StandardCharsets.UTF_8);
    }

    private Result run(Map<String, String> env, String script, String... args) throws Exception {
        return scripts.run(env, script, args);
    }
}
