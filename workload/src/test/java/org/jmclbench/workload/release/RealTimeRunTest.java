package org.jmclbench.workload.release;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.File;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.jmclbench.core.policy.OverrunPolicy;
import org.jmclbench.workload.RunOptions;
import org.jmclbench.workload.WorkloadMain;
import org.jmclbench.workload.data.Dataset;
import org.jmclbench.workload.data.DatasetReader;
import org.jmclbench.core.timeline.Timeline;
import org.jmclbench.core.mcl.AbortSignal;
import org.jmclbench.core.mcl.Localizer;
import org.jmclbench.workload.mcl.Localizers;
import org.jmclbench.core.mcl.MclConfig;
import org.jmclbench.core.record.JobRecords;
import org.jmclbench.workload.testing.SyntheticDataset;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/** Real-time runs of the MCL through the engine: state integrity under termination, and outputs. */
@Timeout(value = 60, unit = TimeUnit.SECONDS)
class RealTimeRunTest {
    @TempDir
    File tmp;

    /**
     * An overloaded terminate run (many particles, timeline replayed 10x faster) aborts jobs in
     * the middle; replaying only the completed jobs, in order, on a fresh localizer with the
     * same seed must reproduce every recorded estimate bit for bit: an aborted job left no trace,
     * not even in the random generator.
     */
    @Test
    void terminatedJobsLeaveTheStateUntouched() throws Exception {
        for (MclConfig.Memory memory : MclConfig.Memory.values()) {
            Dataset d = DatasetReader.readFolder(SyntheticDataset.write(new File(tmp, "data-" + memory), 2.0, 1, true, false));
            Timeline t = d.timeline();
            MclConfig config = MclConfig.builder().particles(40_000).memory(memory).seed(7).build();
            RunOptions options = new RunOptions();
            options.policy = OverrunPolicy.TERMINATE;
            options.particles = config.particles;
            options.memory = memory;
            options.seed = 7;
            options.timeScale = 0.1;
            JobRecords records = new JobRecords(t, false);
            Localizer live = create(config, d);
            RealTimeRun.run(options, d, t, live, records, tmp, System.err);

            int aborted = 0;
            int completed = 0;
            Localizer replay = create(config, d);
            for (int k = 0; k < t.size(); k++) {
                if (records.outcome[k] == JobRecords.TERMINATED && records.startNs[k] >= 0) {
                    aborted++;
                }
                if (!records.completed(k)) {
                    continue;
                }
                completed++;
                int i = t.taskIndex(k);
                assertTrue(t.task(k) == Timeline.PREDICT
                        ? replay.predict(d.odoDx[i], d.odoDy[i], d.odoDtheta[i], AbortSignal.NEVER)
                        : replay.update(d.laserAngle[i], AbortSignal.NEVER));
                assertEquals(replay.estimateX(), records.estX[k], 0.0, memory + " event " + k);
                assertEquals(replay.estimateY(), records.estY[k], 0.0, memory + " event " + k);
                assertEquals(replay.estimateTheta(), records.estTheta[k], 0.0, memory + " event " + k);
            }
            assertTrue(aborted >= 1, memory + ": no job was aborted mid-way; the test proves nothing");
            assertTrue(completed >= 1, memory + ": no job completed");
            assertEquals(live.estimateX(), replay.estimateX(), 0.0);
        }
    }

    /**
     * A preallocated run, even without warm-up, allocates nothing on the engine's threads in the
     * measured window (class loading is done before it): under 512 bytes for ~115 jobs, where a
     * single 16-byte object per job would show as 1.8 KB.
     */
    @Test
    void aPreallocatedRunAllocatesNothingInTheMeasuredWindow() throws Exception {
        Dataset d = DatasetReader.readFolder(SyntheticDataset.write(new File(tmp, "data"), 4.0, 3, true, false));
        Timeline t = d.timeline();
        RunOptions options = new RunOptions();
        options.particles = 300;
        options.timeScale = 0.25;
        options.covariance = true;
        JobRecords records = new JobRecords(t, true);
        JavaSeFacts facts = RealTimeRun.run(options, d, t,
                create(options.mclConfig(), d), records, tmp, System.err);
        Long allocated = facts.allocatedBytes();
        if (allocated != null) {
            assertTrue(allocated < 512, "allocated " + allocated + " bytes");
        }
        assertEquals(0, facts.warmupEvents());
    }

    private static Localizer create(MclConfig c, Dataset d) {
        return Localizers.create(c, d.playground, d.startX, d.startY, d.startTheta);
    }

    /** The whole run tree of FORMATS.md section 3 for each policy, through the workload's main. */
    @Test
    void everyPolicyWritesTheWholeRunTree() throws Exception {
        File data = SyntheticDataset.write(new File(tmp, "data"), 1.5, 1, true, false);
        File odo = new File(data, "odometry.txt");
        File laser = new File(data, "laser.txt");
        File real = new File(data, "real.txt");
        File out = new File(tmp, "out");
        String[][] policies = {{"SkipTest", "--policy", "skip"}, {"TermTest", "-T"}, {"QueueTest", "--policy", "queue"}};
        for (String[] p : policies) {
            java.util.List<String> args = new java.util.ArrayList<>(java.util.Arrays.asList("run", "-p", "200",
                    "-n", "1", "-j", "local", "-O", out.getPath(), "-c", "--gc-log", "--warmup", "0.3",
                    "-odo", odo.getPath(), "-laser", laser.getPath(), "-real", real.getPath()));
            args.addAll(java.util.Arrays.asList(p).subList(1, p.length));
            ByteArrayOutputStream err = new ByteArrayOutputStream();
            int code = WorkloadMain.run(args.toArray(new String[0]), new PrintStream(new ByteArrayOutputStream()),
                    new PrintStream(err, true, "UTF-8"));
            assertEquals(0, code, p[0] + ": " + err.toString("UTF-8"));
            File dir = new File(out, "local/cov/200/" + p[0] + "/1");
            assertTrue(dir.isDirectory(), dir + " missing");
            for (String f : new String[] {"odoData.txt", "laserData.txt", "position.txt", "positionDeviation.txt",
                    "covariance.txt", "data.txt", "summary.json", "gc.log"}) {
                assertTrue(new File(dir, f).isFile(), p[0] + ": " + f + " missing");
            }
            int jobs = 0;
            for (String f : new String[] {"odoData.txt", "laserData.txt"}) {
                List<String> lines = Files.readAllLines(new File(dir, f).toPath(), StandardCharsets.UTF_8);
                assertEquals("# index release_ns start_ns end_ns deadline_ns outcome cpu_ns abort_ns seen_ns", lines.get(0));
                for (String line : lines.subList(1, lines.size())) {
                    String[] c = line.split(" ");
                    assertEquals(9, c.length, f + ": " + line);
                    assertTrue(c[5].matches("done|late|skipped|terminated"), f + ": " + line);
                    assertTrue(Long.parseLong(c[4]) > Long.parseLong(c[1]), "deadline after release: " + line);
                    long start = Long.parseLong(c[2]);
                    long abort = Long.parseLong(c[7]);
                    // abort_ns: where an abort took hold, within the job; asked only under terminate
                    assertTrue(abort == -1 || p[0].equals("TermTest") && start <= abort && abort < Long.parseLong(c[3]),
                            f + ": " + line);
                    assertFalse(c[5].equals("terminated") && start >= 0 && abort < 0, "an aborted job was asked: " + line);
                    long seen = Long.parseLong(c[8]);
                    // seen_ns: when the job's poll saw that abort, between it and the job's end
                    assertTrue(seen == -1 || abort >= 0 && abort <= seen && seen <= Long.parseLong(c[3]), f + ": " + line);
                    jobs++;
                }
            }
            Dataset d = DatasetReader.readFiles(odo, laser, real);
            assertEquals(d.odometryCount() + d.laserCount(), jobs);
            String summary = new String(Files.readAllBytes(new File(dir, "summary.json").toPath()),
                    StandardCharsets.UTF_8);
            for (String key : new String[] {"\"releaseJitterNs\"", "\"taskLatencyNs\"", "\"responseTimeNs\"",
                    "\"cpuNs\"", "\"dispatcherLatenessNs\"", "\"engine\"", "\"status\": \"complete\""}) {
                assertTrue(summary.replace("\":\"", "\": \"").contains(key), p[0] + ": " + key + " missing");
            }
            List<String> dataTxt = Files.readAllLines(new File(dir, "data.txt").toPath(), StandardCharsets.UTF_8);
            assertEquals(7, dataTxt.size());
        }
    }

    /**
     * {@code --no-cpu-time}: no job of a javase or an ideal run has a CPU time (cpu_ns -1), and
     * summary.json records the option and the engine's clock as off; without it the jobs have one.
     */
    @Test
    void noCpuTimeLeavesTheCpuColumnAtMinusOne() throws Exception {
        File data = SyntheticDataset.write(new File(tmp, "data"), 1.5, 1, true, false);
        File out = new File(tmp, "out");
        String[][] runs = {{"SkipTest", "1", "--no-cpu-time"}, {"IdealTest", "1", "--ideal", "--no-cpu-time"},
            {"SkipTest", "2"}};
        boolean clock = ThreadCpuClock.probe().usable();
        for (String[] r : runs) {
            java.util.List<String> args = new java.util.ArrayList<>(java.util.Arrays.asList("-p", "100", "-j", "local",
                    "-O", out.getPath(), "--dataset", data.getPath(), "--time-scale", "0.5", "-n", r[1]));
            args.addAll(java.util.Arrays.asList(r).subList(2, r.length));
            boolean off = args.contains("--no-cpu-time");
            ByteArrayOutputStream err = new ByteArrayOutputStream();
            int code = WorkloadMain.run(args.toArray(new String[0]), new PrintStream(new ByteArrayOutputStream()),
                    new PrintStream(err, true, "UTF-8"));
            assertEquals(0, code, args + ": " + err.toString("UTF-8"));
            File dir = new File(out, "local/nocov/100/" + r[0] + "/" + r[1]);
            int measured = 0;
            int ran = 0;
            for (String f : new String[] {"odoData.txt", "laserData.txt"}) {
                for (String line : Files.readAllLines(new File(dir, f).toPath(), StandardCharsets.UTF_8)) {
                    String[] c = line.split(" ");
                    if (line.startsWith("#") || Long.parseLong(c[2]) < 0) {
                        continue;
                    }
                    ran++;
                    measured += Long.parseLong(c[6]) >= 0 ? 1 : 0;
                }
            }
            assertTrue(ran > 0, args + ": no job ran");
            assertEquals(off || !clock ? 0 : ran, measured, args + ": jobs with a CPU time");
            String summary = new String(Files.readAllBytes(new File(dir, "summary.json").toPath()),
                    StandardCharsets.UTF_8);
            assertTrue(summary.contains("\"cpuTime\": " + !off), args + ": parameters.cpuTime");
            if (off && r[0].equals("SkipTest")) {
                assertTrue(summary.contains("\"cpuTime\": \"" + ThreadCpuClock.OFF + "\""), args + ": engine.cpuTime");
            }
        }
    }
}
