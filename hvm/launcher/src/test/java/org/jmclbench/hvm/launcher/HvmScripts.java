package org.jmclbench.hvm.launcher;

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

/** Runs an hvm/*.sh script as a user would, in a folder of the test's, and keeps what it said. */
final class HvmScripts {
    private final Path hvm;
    private final Path dir;

    /** What a script left: its exit code, standard output and standard error. */
    static final class Result {
        final int exit;
        final String out;
        final String err;

        Result(int exit, String out, String err) {
            this.exit = exit;
            this.out = out;
            this.err = err;
        }
    }

    /** The project's hvm/ folder (the test is skipped without one), run from {@code dir}. */
    HvmScripts(Path dir) {
        File home = HvmRunTest.projectHome();
        Assumptions.assumeTrue(home != null, "no hvm/ folder above the working directory");
        this.hvm = home.toPath().resolve("hvm");
        this.dir = dir;
    }

    Path hvm() {
        return hvm;
    }

    /**
     * Runs {@code script} with its own cache in {@code dir} (a case that must end before the tool
     * chain is built leaves it empty) and an HVM_SRC that names nothing (a case that is not found
     * fails fast), then {@code env} on top (a null value removes the variable).
     */
    Result run(Map<String, String> env, String script, String... args) throws Exception {
        List<String> cmd = new ArrayList<>(Collections.singletonList(hvm.resolve(script).toString()));
        cmd.addAll(Arrays.asList(args));
        Path out = dir.resolve("stdout");
        Path err = dir.resolve("stderr");
        ProcessBuilder pb = new ProcessBuilder(cmd).directory(dir.toFile()).redirectOutput(out.toFile())
                .redirectError(err.toFile());
        pb.environment().put("JMCLBENCH_CACHE", dir.resolve("cache").toString());
        pb.environment().put("HVM_SRC", dir.resolve("no-hvm-src").toString());
        for (Map.Entry<String, String> e : env.entrySet()) {
            if (e.getValue() == null) {
                pb.environment().remove(e.getKey());
            } else {
                pb.environment().put(e.getKey(), e.getValue());
            }
        }
        Process p = pb.start();
        if (!p.waitFor(60, TimeUnit.SECONDS)) {
            p.destroyForcibly();
            throw new AssertionError(script + " " + String.join(" ", args) + " did not end");
        }
        return new Result(p.exitValue(), read(out), read(err));
    }

    static String read(Path f) throws Exception {
        return new String(Files.readAllBytes(f), StandardCharsets.UTF_8);
    }
}
