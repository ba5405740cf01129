package org.jmclbench.tooling.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Bad usage of the launcher's own commands ({@code run}, {@code run-hvm}) is one line naming the
 * option and exit code 2, before anything runs; the thesis's command line (no command word) is a
 * run. The launcher is copied into a home whose build is up to date (a stand-in jar, and a stand-in
 * Maven that only says it was called).
 */
class LauncherBadInputTest {

    @TempDir
    Path home;

    private Path out;

    @BeforeEach
    void upToDateHome() throws Exception {
        Path repo = Path.of(System.getProperty("user.dir")).toAbsolutePath().getParent();
        Files.copy(repo.resolve("jmclbench"), home.resolve("jmclbench"));
        executable(Files.createDirectories(home.resolve("bin")).resolve("mvn"),
                "#!/bin/sh\necho built >> \"" + home.resolve("builds") + "\"\n");
        Files.writeString(Files.createDirectories(home.resolve("tooling/target")).resolve("jmclbench-tooling.jar"), "jar");
        out = home.resolve("out");
    }

    @Test
    void runHvmRefusesAnotherEngine() throws Exception {
        for (String[] engine : List.of(new String[] {"--engine", "javase"}, new String[] {"--engine=scj"})) {
            List<String> args = new ArrayList<>(List.of("run-hvm", "-p", "50", "-O", out.toString()));
            args.addAll(List.of(engine));
            Result r = launch(args);
            assertEquals(2, r.exit, r.err);
            assertEquals(1, r.err.strip().lines().count(), "one line: " + r.err);
            assertTrue(r.err.startsWith("jmclbench: --engine: run-hvm runs the hvm engine, not '"
                    + (engine.length == 2 ? "javase" : "scj") + "'"), r.err);
            assertFalse(Files.exists(out), "nothing may run");
        }
    }

    @Test
    void runRefusesAJvmArgumentTheRuntimeRefuses() throws Exception {
        String java = Path.of(System.getProperty("java.home"), "bin", "java").toString();
        Result r = launch(List.of("run", "--java", java, "--jvm-arg", "-XX:+NoSuchFlag", "-p", "50", "-O", out.toString()));
        assertEquals(2, r.exit, r.err);
        assertEquals("jmclbench: --jvm-arg: " + java + " refuses -XX:+NoSuchFlag: Unrecognized VM option 'NoSuchFlag'",
                r.err.strip());
        assertFalse(Files.exists(out), "nothing may run");
        assertFalse(Files.exists(home.resolve("builds")), "refused before the build");
    }

    @Test
    void runPassesOnAJvmArgumentTheRuntimeAccepts() throws Exception {
        // a stand-in JVM: accepts everything, and writes down the command line of the run itself
        Path args = home.resolve("args");
        Path java = executable(home.resolve("bin/fake-java"),
                "#!/bin/sh\nfor a; do [ \"$a\" = -version ] && exit 0; done\necho \"$@\" > \"" + args + "\"\n");
        Result r = launch(List.of("run", "--java", java.toString(), "--jvm-arg", "-Xmx64m", "-p", "50"));
        assertEquals(0, r.exit, r.err);
        String run = Files.readString(args).strip();
        assertTrue(run.startsWith("-Xmx64m -Djmclbench.home="), run);
        assertTrue(run.endsWith("org.jmclbench.workload.WorkloadMain run -p 50"), run);
    }

    @Test
    void theThesisCommandLineWithoutACommandIsARun() throws Exception {
        // the thesis's scripts: java -jar jMCLBench.jar -j sun-java -p $1 -n $i (no command word)
        Path args = home.resolve("args");
        Path java = executable(home.resolve("bin/fake-java"), "#!/bin/sh\necho \"$@\" > \"" + args + "\"\n");
        for (List<String> line : List.of(List.of("-j", "sun-java", "-p", "50", "-n", "2"),
                List.of("-T", "-c", "-O", "out", "-p", "50"),
                List.of("-odo", "o.txt", "-laser", "l.txt", "-real", "r.txt"))) {
            Files.deleteIfExists(args);
            Result r = launch(line, Map.of("JMCLBENCH_JAVA", java.toString()));
            assertEquals(0, r.exit, r.err);
            String run = Files.readString(args).strip();
            assertTrue(run.endsWith("org.jmclbench.workload.WorkloadMain run " + String.join(" ", line)), run);
        }
    }

    private record Result(int exit, String err) {
    }

    private Result launch(List<String> args) throws Exception {
        return launch(args, Map.of());
    }

    private Result launch(List<String> args, Map<String, String> env) throws Exception {
        List<String> cmd = new ArrayList<>(List.of(home.resolve("jmclbench").toString()));
        cmd.addAll(args);
        ProcessBuilder pb = new ProcessBuilder(cmd).redirectOutput(ProcessBuilder.Redirect.DISCARD);
        pb.environment().put("PATH", home.resolve("bin") + ":" + System.getenv("PATH"));
        pb.environment().putAll(env);
        Process p = pb.start();
        String err = new String(p.getErrorStream().readAllBytes(), StandardCharsets.UTF_8);
        assertTrue(p.waitFor(60, TimeUnit.SECONDS), "the launcher hung");
        return new Result(p.exitValue(), err);
    }

    private static Path executable(Path file, String script) throws Exception {
        Files.writeString(file, script);
        Files.setPosixFilePermissions(file, PosixFilePermissions.fromString("rwxr-xr-x"));
        return file;
    }
}
