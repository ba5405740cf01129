package org.jmclbench.workload.conformance;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.File;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
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
    private static final double TOL = 1e-9;
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
        assertEquals(0, make.exitValue(), () -> "make -C native failed:\n" + read(log));
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

        int lines = compareLines(javaRun.resolve("position.txt"), cRun.resolve("position.txt"), true);
        assertTrue(lines > 100, "position.txt has only " + lines + " lines");
        if (cov) {
            compareLines(javaRun.resolve("covariance.txt"), cRun.resolve("covariance.txt"), false);
        }
        Map<String, Double> dj = keyValues(javaRun.resolve("data.txt"));
        Map<String, Double> dc = keyValues(cRun.resolve("data.txt"));
        for (String k : new String[] {"deviationXY", "deviationX", "deviationY", "deviationAngle"}) {
            assertTrue(dj.containsKey(k) && dc.containsKey(k), "data.txt lacks " + k);
            assertTrue(Math.abs(dj.get(k) - dc.get(k)) <= TOL,
                    k + ": Java " + dj.get(k) + ", C " + dc.get(k) + " (" + options + ")");
        }
        // The deadline accounting of summary.json (predict, update, all in order) is the same in both.
        String sj = read(javaRun.resolve("summary.json"));
        String sc = read(cRun.resolve("summary.json"));
        for (String k : new String[] {"released", "completed", "done", "late", "skipped", "terminated", "missCount",
            "deadlineMisses", "missRatio"}) {
            List<String> vj = jsonNumbers(sj, k);
            assertTrue(vj.size() >= 3, "summary.json lacks " + k);
            assertEquals(vj, jsonNumbers(sc, k), k + " in summary.json (Java, C; " + options + ")");
        }
    }

    /** Every value of the key {@code "name": <number>} in the text, in order, as numbers' texts normalised. */
    private static List<String> jsonNumbers(String json, String name) {
        List<String> out = new ArrayList<>();
        java.util.regex.Matcher m = java.util.regex.Pattern.compile("\"" + name + "\": (-?[0-9.eE+-]+)").matcher(json);
        while (m.find()) {
            out.add(Double.toString(Double.parseDouble(m.group(1))));
        }
        return out;
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
        assertEquals(0, p.exitValue(), () -> runtime + " ideal run failed: " + command + "\n" + read(log));
        Path dir = out.resolve(runtime).resolve(cov ? "cov" : "nocov").resolve(particles).resolve("IdealTest")
                .resolve("1");
        assertTrue(Files.isDirectory(dir), "no run folder " + dir);
        return dir;
    }

    /** Compares two files of 'time v1 v2 ...' lines; the last column is an angle when lastIsAngle. */
    private static int compareLines(Path javaFile, Path cFile, boolean lastIsAngle) throws IOException {
        List<double[]> a = rows(javaFile);
        List<double[]> b = rows(cFile);
        assertEquals(a.size(), b.size(), "line counts of " + javaFile.getFileName() + " (Java, C)");
        for (int i = 0; i < a.size(); i++) {
            double[] r = a.get(i);
            double[] s = b.get(i);
            assertEquals(r.length, s.length, javaFile.getFileName() + " row " + (i + 1) + ": column counts");
            assertEquals(r[0], s[0], javaFile.getFileName() + " row " + (i + 1) + ": times");
            for (int c = 1; c < r.length; c++) {
                double d = lastIsAngle && c == r.length - 1 ? VectorFile.circularDistance(r[c], s[c])
                        : Math.abs(r[c] - s[c]);
                int row = i + 1;
                int col = c;
                assertTrue(d <= TOL, () -> javaFile.getFileName() + " row " + row + " column " + col + ": Java "
                        + r[col] + ", C " + s[col] + " (the implementations diverge here)");
            }
        }
        return a.size();
    }

    private static List<double[]> rows(Path p) throws IOException {
        List<double[]> rows = new ArrayList<>();
        for (String line : Files.readAllLines(p, StandardCharsets.UTF_8)) {
            line = line.trim();
            if (line.isEmpty() || line.startsWith("#")) {
                continue;
            }
            String[] t = line.split("\\s+");
            double[] v = new double[t.length];
            for (int i = 0; i < t.length; i++) {
                v[i] = Double.parseDouble(t[i]);
            }
            rows.add(v);
        }
        return rows;
    }

    private static Map<String, Double> keyValues(Path p) throws IOException {
        Map<String, Double> m = new HashMap<>();
        for (String line : Files.readAllLines(p, StandardCharsets.UTF_8)) {
            String[] t = line.trim().split("\\s+");
            if (t.length == 2 && !t[0].startsWith("#")) {
                try {
                    m.put(t[0], Double.parseDouble(t[1]));
                } catch (NumberFormatException e) {
                    // not a number-valued key
                }
            }
        }
        return m;
    }

    private static String read(Path p) {
        try {
            return new String(Files.readAllBytes(p), StandardCharsets.UTF_8);
        } catch (IOException e) {
            return e.toString();
        }
    }
}
