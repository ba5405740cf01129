package org.jmclbench.workload;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.File;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

import org.jmclbench.workload.engine.Engines;
import org.jmclbench.workload.testing.NativeBuild;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The malformed-input corpus of docs/RELIABILITY.md, end to end: every kind of bad dataset
 * (numbers, columns, order, encodings, control characters, empty and huge files, missing and
 * unreadable paths, directories, metadata) given to every engine of the workload (javase, scj;
 * hvm in the HVM launcher's run of this test) and to the C baseline. Each must exit 2 with the same one line, the one expected
 * (file, line, problem), and leave no run folder behind.
 */
public class MalformedInputCorpusTest {
    private static final String ODO = "0.05  0.01  0.0  0.001\n0.10  0.01  0.0  0.001\n";
    private static final String LASER = "0.03  1.5\n0.07  4.0\n";
    private static final String REAL = "0.05  0.5  0.6  0.1\n0.10  0.51  0.6  0.1\n";

    @TempDir
    File tmp;

    /**
     * One kind: the arguments naming its data, and the message every path must print; for an
     * option the data refutes, the option, which an engine may refuse outright (the hvm engine has
     * no warm-up) before the data is read.
     */
    private static final class Kind {
        final String name;
        final List<String> args;
        final String message;
        final String option;

        Kind(String name, List<String> args, String message, String option) {
            this.name = name;
            this.args = args;
            this.message = message;
            this.option = option;
        }
    }

    private final Map<String, Kind> kinds = new LinkedHashMap<>();

    /** A dataset folder whose files are the good ones but for {@code file}, which holds {@code bytes}. */
    private File folder(String kind, String file, byte[] bytes) throws IOException {
        File dir = new File(tmp, "corpus/" + kind);
        dir.mkdirs();
        write(new File(dir, "odometry.txt"), ODO.getBytes(StandardCharsets.US_ASCII));
        write(new File(dir, "laser.txt"), LASER.getBytes(StandardCharsets.US_ASCII));
        write(new File(dir, "real.txt"), REAL.getBytes(StandardCharsets.US_ASCII));
        if (file != null) {
            write(new File(dir, file), bytes);
        }
        return dir;
    }

    private static void write(File f, byte[] bytes) throws IOException {
        Files.write(f.toPath(), bytes);
    }

    /** A kind whose {@code file} in a folder holds {@code text}; {@code where} is ":line" or "". */
    private void data(String kind, String file, String text, String where, String problem) throws IOException {
        data(kind, file, text.getBytes(StandardCharsets.ISO_8859_1), where, problem);
    }

    private void data(String kind, String file, byte[] bytes, String where, String problem) throws IOException {
        File dir = folder(kind, file, bytes);
        add(kind, Arrays.asList("--dataset", dir.getPath()), new File(dir, file).getPath() + where + ": " + problem);
    }

    private void add(String kind, List<String> args, String message) {
        kinds.put(kind, new Kind(kind, args, "jmclbench: " + message, null));
    }

    /** A kind whose {@code option} the data refutes: the message names the option. */
    private void addOption(String kind, String option, List<String> args, String message) {
        kinds.put(kind, new Kind(kind, args, "jmclbench: " + option + ": " + message, option));
    }

    /**
     * The line {@code engine} must print for {@code k}: the kind's, unless the engine refuses the
     * kind's option outright, whatever the data; then its parser's refusal of that option.
     */
    private static String expected(String engine, Kind k) {
        if (k.option != null) {
            List<String> args = new ArrayList<>(Arrays.asList("--engine", engine));
            args.addAll(k.args);
            try {
                RunOptionsParser.parse(args.toArray(new String[0]));
            } catch (BadInputException e) {
                if (e.getMessage().startsWith(k.option + ": ")) {
                    return "jmclbench: " + e.getMessage();
                }
            }
        }
        return k.message;
    }

    private void buildCorpus() throws IOException, InterruptedException {
        // numbers
        data("word", "odometry.txt", "0.05  zero  0.0  0.001\n", ":1", "not a number: 'zero'");
        data("nan", "odometry.txt", ODO + "0.15  NaN  0  0\n", ":3", "not a finite number: 'NaN'");
        data("infinity", "laser.txt", "0.03  -Infinity\n", ":1", "not a finite number: '-Infinity'");
        data("overflow", "real.txt", "0.05  1e999  0.6  0.1\n", ":1", "not a finite number: '1e999' (overflows)");
        data("hex-float", "odometry.txt", "0x1p-4  0  0  0\n", ":1", "not a number: '0x1p-4'");
        data("type-suffix", "laser.txt", "0.03  1.5d\n", ":1", "not a number: '1.5d'");
        data("bare-exponent", "odometry.txt", "0.05  1e  0  0\n", ":1", "not a number: '1e'");
        data("decimal-comma", "real.txt", "0,05  0.5  0.6  0.1\n", ":1", "not a number: '0,05'");
        // beyond the data's range: a time whose nanoseconds overflow the release times, a non-physical increment
        // (ideal runs, checked alike: were the times let through, a real-time run would wait for years)
        File late = folder("time-beyond-range", "laser.txt", (LASER + "1.0e10  4.0\n").getBytes(StandardCharsets.US_ASCII));
        add("time-beyond-range", Arrays.asList("--dataset", late.getPath(), "--ideal"),
                new File(late, "laser.txt").getPath() + ":3: out of range: '1.0e10' (more than 1e9 in magnitude)");
        data("huge-increment", "odometry.txt", "0.05  1e308  0.0  0.001\n", ":1",
                "out of range: '1e308' (more than 1e9 in magnitude)");
        File scaled = folder("time-scale-beyond-range", "laser.txt",
                (LASER + "5e6  4.0\n").getBytes(StandardCharsets.US_ASCII));
        add("time-scale-beyond-range", Arrays.asList("--dataset", scaled.getPath(), "--time-scale", "1000", "--ideal"),
                "--time-scale: scales the last time of " + new File(scaled, "laser.txt").getPath()
                        + " past 1e9 s, the largest time of a run");
        // a warm-up (data seconds, whatever the time scale) that leaves no event after it: 0.10 s is the last time
        File warm = folder("warmup-at-last-event", null, null);
        String leavesNone = "reaches the last time of " + new File(warm, "odometry.txt").getPath()
                + ": a warm-up replays the data before it and must leave an event after it";
        addOption("warmup-at-last-event", "--warmup", Arrays.asList("--dataset", warm.getPath(), "--warmup", "0.1"),
                leavesNone);
        addOption("warmup-past-data-ideal", "--warmup",
                Arrays.asList("--dataset", warm.getPath(), "--warmup", "1000", "--ideal"), leavesNone);
        // what a value means: a laser angle in [0, 2pi), the ground truth at the odometry times
        data("laser-angle-negative", "laser.txt", "0.03  -7\n", ":1",
                "angle -7 is not in [0, 2pi) (the beacon's angle from the heading)");
        data("laser-angle-two-pi", "laser.txt", LASER + "0.08  6.283185307179586\n", ":3",
                "angle 6.283185307179586 is not in [0, 2pi) (the beacon's angle from the heading)");
        File offTimes = folder("real-off-odometry-times", "real.txt",
                "0.05  0.5  0.6  0.1\n0.12  0.51  0.6  0.1\n".getBytes(StandardCharsets.US_ASCII));
        add("real-off-odometry-times", Arrays.asList("--dataset", offTimes.getPath()), new File(offTimes, "real.txt").getPath()
                + ":2: time 0.12 is not that of record 2 of " + new File(offTimes, "odometry.txt").getPath()
                + " (the ground truth is at the odometry times)");
        File fewer = folder("real-fewer-records", "real.txt", "0.05  0.5  0.6  0.1\n".getBytes(StandardCharsets.US_ASCII));
        add("real-fewer-records", Arrays.asList("--dataset", fewer.getPath()), new File(fewer, "real.txt").getPath()
                + ": 1 records for the 2 of " + new File(fewer, "odometry.txt").getPath()
                + " (the ground truth is at the odometry times)");
        // columns
        data("too-few-columns", "odometry.txt", ODO + "0.15  0.01  0.0\n", ":3", "expected 4 columns but found 3");
        data("too-many-columns", "laser.txt", "0.03  1.5  2\n", ":1", "expected 2 columns but found 3");
        data("trailing-comment", "laser.txt", "0.03  1.5  # beacon 1\n", ":1", "expected 2 columns but found 5");
        // order
        data("unsorted", "odometry.txt", ODO + "0.08  0  0  0\n", ":3",
                "time 0.08 is before the previous line's (not sorted by time)");
        data("negative-time", "real.txt", "-0.05  0.5  0.6  0.1\n", ":1", "negative time -0.05");
        // encodings
        data("utf8-bom", "odometry.txt", "\u00ef\u00bb\u00bf" + ODO, ":1", "not a number: '\\xef\\xbb\\xbf0.05'");
        data("utf16", "laser.txt", LASER.getBytes(StandardCharsets.UTF_16LE), ":1", "expected 2 columns but found 3");
        data("no-break-space", "odometry.txt", "0.05\u00c2\u00a00.01  0.0  0.001\n", ":1",
                "expected 4 columns but found 3");
        // control characters
        data("nul-after-numbers", "odometry.txt", "0.05  0.01  0.0  0.001\0junk\n", ":1",
                "not a number: '0.001\\x00junk'");
        data("lone-cr-line-ends", "laser.txt", "0.03  1.5\r0.07  4.0\r", ":1", "expected 2 columns but found 3");
        data("vertical-tab", "laser.txt", "0.03\u000b1.5\n", ":1", "expected 2 columns but found 1");
        data("escape-sequence", "laser.txt", "0.03  \u001b[31m1.5\n", ":1", "not a number: '\\x1b[31m1.5'");
        // empty and huge
        data("empty", "real.txt", "", "", "empty file (no data lines)");
        data("comments-only", "laser.txt", "# laser\n\n   \n", "", "empty file (no data lines)");
        StringBuilder huge = new StringBuilder(12_000_000);
        for (int i = 1; i <= 200_000; i++) {
            huge.append(String.format(java.util.Locale.ROOT, "%.16e  0.01  0.0  0.001\n", i * 0.05));
        }
        huge.append("1.0e5  0.01  0.0\n");
        data("huge-file", "odometry.txt", huge.toString(), ":200001", "expected 4 columns but found 3");
        StringBuilder wide = new StringBuilder("0.03");
        for (int i = 0; i < 200_000; i++) {
            wide.append(" 1");
        }
        data("huge-line", "laser.txt", wide.append('\n').toString(), ":1", "expected 2 columns but found 200001");
        // paths
        File missing = folder("missing-file", null, null);
        Files.delete(new File(missing, "laser.txt").toPath());
        add("missing-file", Arrays.asList("--dataset", missing.getPath()), new File(missing, "laser.txt").getPath()
                + ": no such file");
        File none = new File(tmp, "corpus/no-such-folder");
        add("missing-folder", Arrays.asList("--dataset", none.getPath()), none.getPath() + ": no such dataset folder");
        File dirs = folder("directory", null, null);
        Files.delete(new File(dirs, "real.txt").toPath());
        assertTrue(new File(dirs, "real.txt").mkdir());
        add("directory", Arrays.asList("--dataset", dirs.getPath()), new File(dirs, "real.txt").getPath()
                + ": is a directory");
        File fifo = folder("fifo", null, null);
        Files.delete(new File(fifo, "odometry.txt").toPath());
        assertEquals(0, new ProcessBuilder("mkfifo", new File(fifo, "odometry.txt").getPath()).start().waitFor());
        add("fifo", Arrays.asList("--dataset", fifo.getPath()), new File(fifo, "odometry.txt").getPath()
                + ": not a regular file");
        File dangling = folder("dangling-link", null, null);
        Files.delete(new File(dangling, "laser.txt").toPath());
        Files.createSymbolicLink(new File(dangling, "laser.txt").toPath(), new File(tmp, "gone.txt").toPath());
        add("dangling-link", Arrays.asList("--dataset", dangling.getPath()), new File(dangling, "laser.txt").getPath()
                + ": no such file");
        File files = folder("io-error", null, null);
        add("io-error", Arrays.asList("-odo", "/proc/self/mem", "-laser", new File(files, "laser.txt").getPath(),
            "-real", new File(files, "real.txt").getPath()), "/proc/self/mem: cannot read");
        if (!"root".equals(System.getProperty("user.name"))) {
            // root reads whatever the mode says; the kind is tried where it can be
            File locked = folder("permission-denied", null, null);
            assertTrue(new File(locked, "real.txt").setReadable(false, false));
            add("permission-denied", Arrays.asList("--dataset", locked.getPath()), new File(locked, "real.txt").getPath()
                    + ": permission denied");
        }
        // dataset.properties
        data("metadata-number", "dataset.properties", "scenario=x\nplayground.width=wide\n", ":2",
                "playground.width: not a number: 'wide'");
        data("metadata-colon", "dataset.properties", "start.x: 0.5\n", ":1", "expected key=value");
        data("metadata-partial-start", "dataset.properties", "start.x=0.5\nstart.theta=0\n", "", "start.y: missing");
        data("metadata-empty-beacon", "dataset.properties", "beacons=0,1;;3,0\n", ":1",
                "beacons: expected x,y;x,y;... (1 to 32 beacons)");
        data("metadata-non-ascii", "dataset.properties", "scenario=caf\u00c3\u00a9\n", ":1",
                "not printable ASCII: byte 0xc3");
        data("metadata-zero-size", "dataset.properties", "playground.height=0\n", ":1",
                "playground.height: must be positive");
        data("metadata-out-of-range", "dataset.properties", "start.x=-2e9\nstart.y=0\nstart.theta=0\n", ":1",
                "start.x: out of range: '-2e9' (more than 1e9 in magnitude)");
    }

    /** Exit code and stderr of one path on one kind. */
    private static final class Outcome {
        final int code;
        final String err;

        Outcome(int code, String err) {
            this.code = code;
            this.err = err;
        }
    }

    private static Outcome java(String engine, List<String> data, File out) {
        List<String> args = new ArrayList<>(Arrays.asList("run", "--engine", engine, "-O", out.getPath(), "-p", "50",
            "--time-scale", "0.01"));
        args.addAll(data);
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        int code = WorkloadMain.run(args.toArray(new String[0]), new PrintStream(new ByteArrayOutputStream()),
                new PrintStream(err));
        return new Outcome(code, new String(err.toByteArray(), StandardCharsets.UTF_8));
    }

    private static Outcome c(File binary, List<String> data, File out) throws IOException {
        List<String> cmd = new ArrayList<>(Arrays.asList(binary.getPath(), "run", "-O", out.getPath(), "-p", "50",
            "--time-scale", "0.01", "--no-fifo"));
        cmd.addAll(data);
        Process p = new ProcessBuilder(cmd).redirectOutput(new File("/dev/null")).start();
        String err = NativeBuild.readAll(p.getErrorStream());
        return new Outcome(NativeBuild.waitFor(p), err);
    }

    @Test
    public void everyKindIsRejectedAlikeByEveryEngineWithItsLineAndNothingRecorded() throws Exception {
        buildCorpus();
        File binary = NativeBuild.target("build/jmclbench-native");
        assertTrue(kinds.size() >= 30, kinds.size() + " kinds");
        for (Kind k : kinds.values()) {
            Map<String, Outcome> outcomes = new LinkedHashMap<>();
            // every engine on the class path: the hvm engine's launcher reruns this test with its own
            for (String engine : Engines.names().split("\\|")) {
                File out = new File(tmp, "out-" + engine + "-" + k.name);
                outcomes.put(engine, java(engine, k.args, out));
                assertFalse(out.exists(), k.name + ": " + engine + " wrote " + out);
            }
            File out = new File(tmp, "out-native-" + k.name);
            outcomes.put("native", c(binary, k.args, out));
            assertFalse(out.exists(), k.name + ": native wrote " + out);
            for (Map.Entry<String, Outcome> e : outcomes.entrySet()) {
                String who = k.name + " on " + e.getKey();
                assertEquals(2, e.getValue().code, who + ": " + e.getValue().err);
                String message = e.getKey().equals("native") ? k.message : expected(e.getKey(), k);
                assertEquals(message + "\n", e.getValue().err, who);
            }
        }
    }
}
