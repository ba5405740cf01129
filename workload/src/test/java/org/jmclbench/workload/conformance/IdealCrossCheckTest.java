package org.jmclbench.workload.conformance;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.File;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * Whole runs in both languages: the Java workload and the C baseline, each in an ideal run
 * ({@code --ideal}) on the shipped data/match-short with the same options, must write the
 * same estimates.
 *
 * <p>Tolerance: 1e-9 (m, rad) on every line of position.txt and covariance.txt and on the mean
 * deviations of data.txt, for the whole run. Measured on this machine: at most 2.7e-15, with
 * 70-90 of 400 lines bit-identical: the libraries' atan2/exp/sin/cos differ only in last bits,
 * and such a difference changes the run only if it flips a resampling decision, which needs a
 * weight sum within about 1e-15 of a threshold: about 2 N^2 * 1e-15 per update, below 1e-6
 * per run for these sizes. So a difference above 1e-9 is a real divergence of the two
 * implementations (one formula, order of draws or rule changed), not rounding.
 */
class IdealCrossCheckTest {
    private static Path home;
    private static Path nativeProgram;

    @BeforeAll
    static void buildNative() throws Exception {
        home = VectorFile.projectHome();
        Assumptions.assumeTrue(Files.isRegularFile(home.resolve("native/Makefile")),
                "the native baseline is not in this checkout");
        Path log = Files.createTempFile("jmclbench-make", ".log");
        Process make = new ProcessBuilder("make", "-s", "-C", home.resolve("native").toString(), "all")
                .redirectErrorStream(true).redirectOutput(log.toFile()).start();
        assertTrue(make.waitFor(300, TimeUnit.SECONDS), "make -C native did not finish in 300 s");
        assertEquals(0, make.exitValue(), () -> "make -C native failed:\n" + IdealRunComparison.read(log));
        nativeProgram = home.resolve("native/build/jmclbench-native");
        assertTrue(Files.isExecutable(nativeProgram), nativeProgram + " was not built");
    }

    @ParameterizedTest
    @ValueSource(strings = {
        "-p 400 --seed 1",
        "-p 500 --seed 7 --estimate best --resample multinomial -c --memory allocating",
        "-p 300 --seed 3 --init uniform -c",
    })
    void javaAndCWriteTheSameEstimates(String options, @org.junit.jupiter.api.io.TempDir Path tmp) throws Exception {
        List<String> opts = Arrays.asList(options.split(" "));
        String particles = opts.get(opts.indexOf("-p") + 1);
        boolean cov = opts.contains("-c");

        List<String> java = new ArrayList<>(Arrays.asList(
                new File(System.getProperty("java.home"), "bin/java").getPath(),
                "-cp", System.getProperty("java.class.path"),
                "org.jmclbench.workload.WorkloadMain"));
        Path javaRun = run(java, opts, tmp.resolve("java"), "java", particles, cov);
        Path cRun = run(new ArrayList<>(Arrays.asList(nativeProgram.toString())), opts, tmp.resolve("c"), "c",
                particles, cov);

        IdealRunComparison c = IdealRunComparison.of(javaRun, "Java", cRun, "C", cov);
        assertNull(c.difference, () -> c.difference + "; " + options);
        assertTrue(c.positionLines > 100, "position.txt has only " + c.positionLines + " lines");
    }

    /** Runs one ideal run and returns its run folder. */
    private static Path run(List<String> command, List<String> opts, Path out, String runtime, String particles,
            boolean cov) throws Exception {
        command.addAll(Arrays.asList("run", "--ideal", "--dataset", home.resolve("data/match-short").toString(),
                "-O", out.toString(), "-j", runtime, "-n", "1"));
        command.addAll(opts);
        Files.createDirectories(out);
        Path log = out.resolve("log.txt");
        Process p = new ProcessBuilder(command).redirectErrorStream(true).redirectOutput(log.toFile()).start();
        assertTrue(p.waitFor(300, TimeUnit.SECONDS), runtime + " ideal run did not finish in 300 s: " + command);
        assertEquals(0, p.exitValue(),
                () -> runtime + " ideal run failed: " + command + "\n" + IdealRunComparison.read(log));
        Path dir = out.resolve(runtime).resolve(cov ? "cov" : "nocov").resolve(particles).resolve("IdealTest")
                .resolve("1");
        assertTrue(Files.isDirectory(dir), "no run folder " + dir);
        return dir;
    }
}
