package org.jmclbench.workload.conformance;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.File;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.Random;

import org.jmclbench.workload.WorkloadMain;
import org.jmclbench.workload.data.DatasetMetadata;
import org.jmclbench.workload.testing.NativeBuild;
import org.jmclbench.workload.testing.SyntheticDataset;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * A randomized differential check of whole ideal runs: for each case a small dataset and
 * random valid filter options (particle count from 1, estimate, resampling, initialisation,
 * covariance, seed, time scale, warm-up), run by the Java workload in each memory style
 * (preallocated, allocating, scoped) and by the C baseline in each of its own (preallocated,
 * allocating); each must agree with Java's preallocated run as {@link IdealRunComparison}
 * states, and the styles of one language write bit-identical estimates (ALGORITHM.md 9). Where
 * {@link IdealCrossCheckTest} holds three fixed option sets on data/match-short, this one
 * reaches the options and datasets nobody chose by hand. Also, a case's options made invalid
 * in one value must be refused by both alike: exit 2, the same one-line message.
 *
 * <p>CI runs a few fixed cases (deterministic). A long run, which counts every disagreement
 * before failing: {@code bench/crosscheck.sh} (system properties
 * {@code jmclbench.crosscheck.cases}, {@code .first} and {@code .datasets}: a folder of
 * datasets, e.g. from {@code jmclbench generate}, used in turn instead of the synthetic one).
 */
class RandomizedCrossCheckTest {
    private static final int CASES = Integer.getInteger("jmclbench.crosscheck.cases", 6);
    private static final long FIRST = Long.getLong("jmclbench.crosscheck.first", 1L);
    private static final String DATASETS = System.getProperty("jmclbench.crosscheck.datasets");
    /** The Java memory styles, each with the engine that offers it (the ideal run ignores the engine otherwise). */
    private static final String[][] JAVA_STYLES = {{"--memory", "preallocated"}, {"--memory", "allocating"},
        {"--engine", "scj", "--memory", "scoped"}};
    private static final String[] C_STYLES = {"preallocated", "allocating"};

    @Test
    void javaInEveryMemoryStyleAndCWriteTheSameEstimates(@TempDir Path tmp) throws Exception {
        File c = NativeBuild.target("build/jmclbench-native");
        List<File> datasets = datasets();
        List<String> disagreements = new ArrayList<>();
        int runs = 0;
        double largest = 0;
        for (long k = FIRST; k < FIRST + CASES; k++) {
            Random r = new Random(k);
            Path dir = tmp.resolve("case" + k);
            File dataset = datasets.isEmpty() ? synthetic(r, dir.resolve("ds").toFile())
                    : datasets.get((int) ((k - FIRST) % datasets.size()));
            List<String> options = options(r, dataset);
            boolean cov = options.contains("-c");
            String what = "case " + k + ": " + dataset + " " + String.join(" ", options);

            Path reference = null;
            String referenceName = null;
            for (String[] style : JAVA_STYLES) {
                String name = "java-" + style[style.length - 1];
                List<String> args = new ArrayList<>(options);
                args.addAll(Arrays.asList(style));
                Path run = java(args, dataset, dir.resolve(name), name, cov, what);
                runs++;
                if (reference == null) {
                    reference = run;
                    referenceName = name;
                    continue;
                }
                largest = check(reference, referenceName, run, name, cov, what, disagreements, largest);
                identical(reference, referenceName, run, name, cov, what, disagreements);
            }
            Path cReference = null;
            for (String style : C_STYLES) {
                String name = "c-" + style;
                List<String> args = new ArrayList<>(options);
                args.addAll(Arrays.asList("--memory", style));
                Path run = c(c, args, dataset, dir.resolve(name), name, cov, what);
                runs++;
                largest = check(reference, referenceName, run, name, cov, what, disagreements, largest);
                if (cReference == null) {
                    cReference = run;
                } else {
                    identical(cReference, "c-" + C_STYLES[0], run, name, cov, what, disagreements);
                }
            }
            refusedAlike(c, r, dataset, options, dir.resolve("refused"), what);
            deleteTree(dir.toFile()); // a long run keeps only what it compares next
        }
        System.out.printf(Locale.ROOT, "crosscheck: %d cases (%d..%d), %d runs, %d disagreements, largest "
                + "difference within tolerance %.3g%n", CASES, FIRST, FIRST + CASES - 1, runs,
                disagreements.size(), largest);
        for (String d : disagreements) {
            System.out.println("crosscheck: DISAGREE " + d);
        }
        assertTrue(disagreements.isEmpty(), disagreements.size() + " of " + CASES + " cases disagree; the first: "
                + (disagreements.isEmpty() ? "" : disagreements.get(0)));
    }

    /** Compares a run with the reference; records a disagreement; returns the largest difference so far. */
    private static double check(Path reference, String referenceName, Path run, String name, boolean cov,
            String what, List<String> disagreements, double largest) throws IOException {
        IdealRunComparison cmp = IdealRunComparison.of(reference, referenceName, run, name, cov);
        if (cmp.difference != null) {
            disagreements.add(what + ": " + cmp.difference);
            return largest;
        }
        return Math.max(largest, cmp.largest);
    }

    /**
     * The memory styles of one language run the same arithmetic in the same order (ALGORITHM.md
     * section 9): their estimates and covariances are bit-identical, so their files are too.
     */
    private static void identical(Path reference, String referenceName, Path run, String name, boolean cov,
            String what, List<String> disagreements) throws IOException {
        for (String file : cov ? new String[] {"position.txt", "covariance.txt"} : new String[] {"position.txt"}) {
            if (!Arrays.equals(Files.readAllBytes(reference.resolve(file)), Files.readAllBytes(run.resolve(file)))) {
                disagreements.add(what + ": " + file + " differs between " + referenceName + " and " + name
                        + " (memory styles are bit-identical)");
            }
        }
    }

    /**
     * A small synthetic dataset (SyntheticDataset's circle or standing robot, 0.5-4 s): without
     * dataset.properties (the thesis's field and start pose apply), with the simulation's own,
     * or with a random field (size, 1 to 32 beacons anywhere, start pose) the sensor data were
     * not made on: the filter still runs, and both implementations must read and use it alike.
     */
    private static File synthetic(Random r, File dir) throws IOException {
        double duration = 0.5 + 0.05 * r.nextInt(71);
        int metadata = r.nextInt(3);
        SyntheticDataset.write(dir, duration, r.nextLong(), r.nextInt(4) != 0, metadata == 1);
        if (metadata == 2) {
            double w = 0.5 + 5.5 * r.nextDouble();
            double h = 0.5 + 5.5 * r.nextDouble();
            int n = 1 + r.nextInt(DatasetMetadata.MAX_BEACONS);
            StringBuilder beacons = new StringBuilder();
            for (int b = 0; b < n; b++) {
                beacons.append(b == 0 ? "" : ";").append(String.format(Locale.ROOT, "%.6f,%.6f",
                        (1.4 * r.nextDouble() - 0.2) * w, (1.4 * r.nextDouble() - 0.2) * h));
            }
            List<String> lines = Arrays.asList("format=jmclbench-dataset/1", "scenario=random-field",
                    String.format(Locale.ROOT, "playground.width=%.17g", w),
                    String.format(Locale.ROOT, "playground.height=%.17g", h), "beacons=" + beacons,
                    String.format(Locale.ROOT, "start.x=%.17g", w * r.nextDouble()),
                    String.format(Locale.ROOT, "start.y=%.17g", h * r.nextDouble()),
                    String.format(Locale.ROOT, "start.theta=%.17g", 2 * Math.PI * r.nextDouble()));
            Files.write(new File(dir, "dataset.properties").toPath(), lines, StandardCharsets.UTF_8);
        }
        return dir;
    }

    /** Random valid options of the filter and of the ideal run for a dataset. */
    private static List<String> options(Random r, File dataset) throws IOException {
        List<String> o = new ArrayList<>();
        int[] small = {1, 2, 3, 7, 64, 65};
        int particles = r.nextInt(3) == 0 ? small[r.nextInt(small.length)] : 1 + r.nextInt(400);
        o.addAll(Arrays.asList("-p", Integer.toString(particles)));
        o.addAll(Arrays.asList("--estimate", r.nextBoolean() ? "mean" : "best"));
        o.addAll(Arrays.asList("--resample", r.nextBoolean() ? "systematic" : "multinomial"));
        o.addAll(Arrays.asList("--init", r.nextInt(3) == 0 ? "uniform" : "known"));
        long[] seeds = {0, 1, -1, Long.MIN_VALUE, Long.MAX_VALUE};
        long seed = r.nextInt(4) == 0 ? seeds[r.nextInt(seeds.length)] : r.nextLong();
        o.addAll(Arrays.asList("--seed", Long.toString(seed)));
        if (r.nextBoolean()) {
            o.add("-c");
        }
        if (r.nextInt(3) == 0) {
            String[] scales = {"0.5", "2", "0.37", "1e-6", "1000"};
            o.addAll(Arrays.asList("--time-scale", scales[r.nextInt(scales.length)]));
        }
        double last = lastOdometryTime(dataset);
        if (r.nextInt(3) == 0 && last > 0.2) {
            // a warm-up must leave an event after it; it replays on a throwaway filter
            o.addAll(Arrays.asList("--warmup", String.format(Locale.ROOT, "%.3f", r.nextDouble() * (last - 0.1))));
        }
        return o;
    }

    /**
     * One value of the options made invalid (out of range, not a label, not a number): both
     * implementations must refuse the line with exit 2 and the same one-line message.
     */
    private static void refusedAlike(File c, Random r, File dataset, List<String> options, Path out, String what)
            throws IOException {
        String[][] bad = {{"-p", "0"}, {"-p", "100000001"}, {"-p", "1.5"}, {"--estimate", "Best"},
            {"--resample", "stratified"}, {"--init", ""}, {"--seed", "9223372036854775808"}, {"--seed", "0x10"},
            {"--time-scale", "0"}, {"--time-scale", "1001"}, {"--warmup", "-1"}, {"--warmup", "1e9"},
            {"--memory", "scoped"}, {"--spin-us", "5"}};
        String[] pick = bad[r.nextInt(bad.length)];
        List<String> args = new ArrayList<>(options);
        args.addAll(Arrays.asList(pick));
        List<String> full = command(args, dataset, out, "refused");
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        int javaCode = WorkloadMain.run(full.toArray(new String[0]), new PrintStream(new ByteArrayOutputStream()),
                new PrintStream(err));
        String javaErr = new String(err.toByteArray(), StandardCharsets.UTF_8);
        List<String> cmd = new ArrayList<>();
        cmd.add(c.getPath());
        cmd.addAll(full);
        Process p = new ProcessBuilder(cmd).start();
        p.getOutputStream().close();
        String cOut = NativeBuild.readAll(p.getInputStream());
        String cErr = NativeBuild.readAll(p.getErrorStream());
        int cCode = NativeBuild.waitFor(p);
        String msg = what + " " + String.join(" ", pick) + ": Java " + javaCode + " '" + javaErr + "', C " + cCode
                + " '" + cErr + "' " + cOut;
        assertEquals(2, javaCode, msg);
        assertEquals(2, cCode, msg);
        assertTrue(javaErr.endsWith("\n") && javaErr.indexOf('\n') == javaErr.length() - 1, msg);
        if ("--memory".equals(pick[0])) {
            // scoped is a style of Java's SCJ engines: each says why in its own words
            assertTrue(cErr.startsWith("jmclbench: --memory: ") && javaErr.startsWith("jmclbench: --memory: "), msg);
        } else {
            assertEquals(javaErr, cErr, msg);
        }
        assertTrue(!new File(out.toFile(), "refused").exists(), msg + ": a refused run left a folder");
    }

    /** The run's command line after the program: an ideal run of the dataset into out/runtime. */
    private static List<String> command(List<String> options, File dataset, Path out, String runtime) {
        List<String> cmd = new ArrayList<>(Arrays.asList("run", "--ideal", "--dataset", dataset.getPath(), "-O",
                out.toString(), "-j", runtime, "-n", "1"));
        cmd.addAll(options);
        return cmd;
    }

    /** An ideal run of the workload in this JVM; its run folder. */
    private static Path java(List<String> options, File dataset, Path out, String runtime, boolean cov,
            String what) {
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        int code = WorkloadMain.run(command(options, dataset, out, runtime).toArray(new String[0]),
                new PrintStream(new ByteArrayOutputStream()), new PrintStream(err));
        assertEquals(0, code, () -> what + ": Java (" + runtime + ") failed: "
                + new String(err.toByteArray(), StandardCharsets.UTF_8));
        return runFolder(out, runtime, options, cov);
    }

    /** An ideal run of the C baseline; its run folder. */
    private static Path c(File program, List<String> options, File dataset, Path out, String runtime, boolean cov,
            String what) throws IOException {
        List<String> cmd = new ArrayList<>();
        cmd.add(program.getPath());
        cmd.addAll(command(options, dataset, out, runtime));
        Process p = new ProcessBuilder(cmd).redirectErrorStream(true).start();
        p.getOutputStream().close();
        String log = NativeBuild.readAll(p.getInputStream());
        int code = NativeBuild.waitFor(p);
        assertEquals(0, code, () -> what + ": C (" + runtime + ") failed: " + log);
        return runFolder(out, runtime, options, cov);
    }

    private static Path runFolder(Path out, String runtime, List<String> options, boolean cov) {
        String particles = options.get(options.indexOf("-p") + 1);
        Path dir = out.resolve(runtime).resolve(cov ? "cov" : "nocov").resolve(particles).resolve("IdealTest")
                .resolve("1");
        assertTrue(Files.isDirectory(dir), "no run folder " + dir);
        return dir;
    }

    /** The time of the last odometry event of a dataset (seconds). */
    private static double lastOdometryTime(File dataset) throws IOException {
        double last = 0;
        for (String line : Files.readAllLines(new File(dataset, "odometry.txt").toPath(), StandardCharsets.UTF_8)) {
            line = line.trim();
            if (!line.isEmpty() && !line.startsWith("#")) {
                last = Double.parseDouble(line.split("\\s+")[0]);
            }
        }
        return last;
    }

    /** The datasets of the jmclbench.crosscheck.datasets folder (its subfolders holding odometry.txt), sorted. */
    private static List<File> datasets() {
        List<File> out = new ArrayList<>();
        if (DATASETS != null) {
            File[] dirs = new File(DATASETS).listFiles();
            assertTrue(dirs != null, DATASETS + " is not a folder");
            Arrays.sort(dirs);
            for (File d : dirs) {
                if (new File(d, "odometry.txt").isFile()) {
                    out.add(d);
                }
            }
            assertTrue(!out.isEmpty(), DATASETS + " holds no dataset");
        }
        return out;
    }

    private static void deleteTree(File f) {
        File[] children = f.listFiles();
        if (children != null) {
            for (File child : children) {
                deleteTree(child);
            }
        }
        f.delete();
    }
}
