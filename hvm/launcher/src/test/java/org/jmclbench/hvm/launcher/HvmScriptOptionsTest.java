package org.jmclbench.hvm.launcher;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.File;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Collections;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The hvm/*.sh scripts' command lines: --help prints the script's header, the whole of it and nothing else. */
class HvmScriptOptionsTest {
    private static final List<String> SCRIPTS = Arrays.asList("build-hvm.sh", "build-mission.sh", "difftest.sh", "hvmc.sh",
            "test-patches.sh", "upstream-scj-tests.sh");

    @TempDir
    Path dir;
    private Path hvm;

    @BeforeEach
    void findScripts() {
        File home = HvmRunTest.projectHome();
        Assumptions.assumeTrue(home != null, "no hvm/ folder above the working directory");
        hvm = home.toPath().resolve("hvm");
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
        }
    }

    private static final class Result {
        final int exit;
        final String out;
        final String err;

        Result(int exit, String out, String err) {
            this.exit = exit;
            this.out = out;
            this.err = err;
        }
    }

    private static byte[] bytes(String s) {
        return s.getBytes(StandardCharsets.UTF_8);
    }

    private static String read(Path f) throws Exception {
        return new String(Files.readAllBytes(f), StandardCharsets.UTF_8);
    }

    private Result run(Map<String, String> env, String script, String... args) throws Exception {
        List<String> cmd = new ArrayList<>(Collections.singletonList(hvm.resolve(script).toString()));
        cmd.addAll(Arrays.asList(args));
        Path out = dir.resolve("stdout");
        Path err = dir.resolve("stderr");
        ProcessBuilder pb = new ProcessBuilder(cmd).directory(dir.toFile()).redirectOutput(out.toFile())
                .redirectError(err.toFile());
        // a bad option must be found before the tool chain is built: a cache of its own stays empty
        pb.environment().put("JMCLBENCH_CACHE", dir.resolve("cache").toString());
        // and no source to build it from, so that a case that is not found fails fast
        pb.environment().put("HVM_SRC", dir.resolve("no-hvm-src").toString());
        pb.environment().putAll(env);
        Process p = pb.start();
        if (!p.waitFor(60, TimeUnit.SECONDS)) {
            p.destroyForcibly();
            throw new AssertionError(script + " " + String.join(" ", args) + " did not end");
        }
        return new Result(p.exitValue(), read(out), read(err));
    }
}
