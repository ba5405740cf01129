package org.jmclbench.workload;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.io.File;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.TimeUnit;

import org.jmclbench.workload.engine.Engines;
import org.jmclbench.workload.testing.NativeBuild;
import org.jmclbench.workload.testing.WorkloadCall;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/**
 * Events at the same time (docs/RELEASE-ENGINE.md, "Events at the same time"): every engine
 * decides them in timeline order (odometry first), each as if the one before had just been
 * released and had not started. On a dataset whose every other odometry event has a laser event at
 * its instant, with the robot idle at each instant (jobs of 10 particles, 200 ms apart): under skip
 * the predict runs and the update is skipped, under terminate the predict is superseded before it
 * starts and the update runs, under queue both run. Before the rule, the threads' wake-up order
 * decided: the javase, C and scj engines dropped either event of a pair, the rtsj engine ran both.
 * The engines are those on the class path (the hvm engine's launcher reruns this test with its own)
 * and the C baseline.
 */
@Timeout(value = 300, unit = TimeUnit.SECONDS)
public class CoincidingTimesTest {
    /** Odometry events, 50 ms apart from 50 ms; a laser event at every second one's instant. */
    private static final int ODOMETRY = 10;
    /** Stretches the 50 ms between events so that each job has long ended before the next instant. */
    private static final String TIME_SCALE = "4";

    @TempDir
    File tmp;

    private final WorkloadCall call = new WorkloadCall();

    @Test
    public void everyEngineDecidesTiedEventsInTimelineOrder() throws IOException {
        File ds = writeDataset(new File(tmp, "ties"));
        File binary = NativeBuild.target("build/jmclbench-native");
        List<String> wrong = new ArrayList<>();
        for (String policy : new String[] {"skip", "terminate", "queue"}) {
            String expected = expected(policy);
            Map<String, String> got = new LinkedHashMap<>();
            for (String engine : Engines.names().split("\\|")) {
                if (engine.equals("rtsj")) {
                    for (String design : new String[] {"thesis", "atomic"}) {
                        got.put("rtsj " + design, java(ds, policy, "--engine", "rtsj", "--rtsj-design", design));
                    }
                } else {
                    got.put(engine, java(ds, policy, "--engine", engine));
                }
            }
            got.put("native", c(binary, ds, policy));
            for (Map.Entry<String, String> e : got.entrySet()) {
                if (!expected.equals(e.getValue())) {
                    wrong.add(e.getKey() + " under " + policy + ": " + e.getValue() + ", expected " + expected);
                }
            }
        }
        assertEquals("", String.join("\n", wrong), "per tied instant, predict/update: r ran, s skipped, t terminated");
    }

    /** The rule's outcomes, one predict/update pair per tied instant. */
    private static String expected(String policy) {
        String pair = policy.equals("skip") ? "r/s" : policy.equals("terminate") ? "t/r" : "r/r";
        List<String> pairs = new ArrayList<>();
        for (int i = 0; i < ODOMETRY / 2; i++) {
            pairs.add(pair);
        }
        return String.join(" ", pairs);
    }

    private String java(File ds, String policy, String... engine) throws IOException {
        List<String> args = new ArrayList<>(Arrays.asList("run", "-p", "10", "--policy", policy, "--time-scale",
            TIME_SCALE, "--dataset", ds.getPath(), "-O", new File(tmp, "out").getPath()));
        args.addAll(Arrays.asList(engine));
        String what = String.join(" ", engine) + " --policy " + policy;
        assertEquals(0, call.run(args.toArray(new String[0])), what + ": " + call.err());
        return outcomes(new File(call.out().trim()), what);
    }

    private String c(File binary, File ds, String policy) throws IOException {
        File out = new File(tmp, "out-native-" + policy);
        Process p = new ProcessBuilder(binary.getPath(), "run", "-p", "10", "--policy", policy, "--time-scale",
            TIME_SCALE, "--no-fifo", "--dataset", ds.getPath(), "-O", out.getPath()).redirectErrorStream(true).start();
        String printed = NativeBuild.readAll(p.getInputStream());
        String what = "native --policy " + policy;
        assertEquals(0, NativeBuild.waitFor(p), what + ": " + printed);
        String[] lines = printed.trim().split("\n");
        return outcomes(new File(lines[lines.length - 1].trim()), what);
    }

    /**
     * Per tied instant, the predict's and the update's outcome: r (done or late: it ran), s, t. The
     * events between the instants must have run: nothing else was on the robot.
     */
    private static String outcomes(File run, String what) throws IOException {
        List<String> odo = jobs(new File(run, "odoData.txt"));
        List<String> laser = jobs(new File(run, "laserData.txt"));
        assertEquals(ODOMETRY, odo.size(), what + ": " + odo);
        assertEquals(ODOMETRY / 2, laser.size(), what + ": " + laser);
        List<String> pairs = new ArrayList<>();
        for (int i = 0; i < ODOMETRY; i++) {
            if (i % 2 == 0) {
                assertEquals("r", odo.get(i), what + ": odometry event " + i + " had the robot to itself: " + odo);
            } else {
                pairs.add(odo.get(i) + "/" + laser.get(i / 2));
            }
        }
        return String.join(" ", pairs);
    }

    /** A job file's outcomes, in its order: r, s or t. */
    private static List<String> jobs(File f) throws IOException {
        List<String> r = new ArrayList<>();
        for (String line : Files.readAllLines(f.toPath(), StandardCharsets.UTF_8)) {
            if (!line.startsWith("#")) {
                String outcome = line.trim().split(" ")[5];
                r.add(outcome.equals("done") || outcome.equals("late") ? "r" : outcome.substring(0, 1));
            }
        }
        return r;
    }

    /** Odometry every 50 ms from 50 ms, the laser at every second odometry event's time (same digits). */
    private static File writeDataset(File dir) throws IOException {
        dir.mkdirs();
        StringBuilder odo = new StringBuilder();
        StringBuilder laser = new StringBuilder();
        StringBuilder real = new StringBuilder();
        for (int i = 0; i < ODOMETRY; i++) {
            String t = String.format(Locale.ROOT, "%.16e", 0.05 * (i + 1));
            odo.append(t).append("  1.0e-03  0.0e+00  5.0e-03\n");
            real.append(t).append(String.format(Locale.ROOT, "  %.16e  4.0e-01  %.16e\n", 0.4 + 0.001 * (i + 1),
                0.005 * (i + 1)));
            if (i % 2 == 1) {
                laser.append(t).append(String.format(Locale.ROOT, "  %.16e\n", 1.0 + 0.02 * i));
            }
        }
        Files.write(new File(dir, "odometry.txt").toPath(), odo.toString().getBytes(StandardCharsets.UTF_8));
        Files.write(new File(dir, "laser.txt").toPath(), laser.toString().getBytes(StandardCharsets.UTF_8));
        Files.write(new File(dir, "real.txt").toPath(), real.toString().getBytes(StandardCharsets.UTF_8));
        return dir;
    }
}
