package org.jmclbench.workload.mcl;

import java.io.IOException;
import java.io.PrintWriter;
import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.time.Instant;
import java.util.Locale;

/**
 * Records the attribution fixtures: a periodic job on a handler thread while a noise thread
 * allocates, so that the recording holds GC pauses that overlap jobs. Not part of the build;
 * record-fixtures.sh compiles and runs it on each JDK.
 *
 * <p>Writes {@code jobs.txt} (job lines of docs/FORMATS.md section 3) and {@code clock.txt}
 * ({@code runStartEpochNs runStartNanoTime jvmStartEpochMs}) into the folder given as the first argument.
 * Job 40 is deliberately slow (40 ms of CPU for a 10 ms deadline); the others use 1 ms.
 */
public final class FixtureJobs {
    static final long PERIOD_NS = 20_000_000L;
    static final long DEADLINE_NS = 10_000_000L;
    static final int SLOW_JOB = 40;
    static volatile double sink;
    static volatile boolean stop;

    public static void main(String[] args) throws Exception {
        Path out = Paths.get(args[0]);
        double seconds = Double.parseDouble(args[1]);
        int jobs = (int) (seconds * 1e9 / PERIOD_NS);
        long[][] rec = new long[jobs][5];

        Thread noise = new Thread(FixtureJobs::allocate, "alloc-noise");
        noise.setDaemon(true);
        noise.start();

        long before = System.nanoTime();
        Instant wall = Instant.now();
        long after = System.nanoTime();
        long startNano = before + (after - before) / 2;
        long startEpoch = wall.getEpochSecond() * 1_000_000_000L + wall.getNano();

        ThreadMXBean mx = ManagementFactory.getThreadMXBean();
        Thread.currentThread().setName("handler-predict");
        for (int i = 0; i < jobs; i++) {
            long release = startNano + i * PERIOD_NS;
            long now;
            while ((now = System.nanoTime()) < release) {
                long left = release - now;
                if (left > 200_000) {
                    Thread.sleep(0, 0);
                    Thread.sleep(Math.max(0, (left - 150_000) / 1_000_000), (int) ((left - 150_000) % 1_000_000));
                }
            }
            long cpu0 = mx.getCurrentThreadCpuTime();
            long start = System.nanoTime();
            compute(i == SLOW_JOB ? 40_000_000L : 1_000_000L);
            long end = System.nanoTime();
            long cpu = mx.getCurrentThreadCpuTime() - cpu0;
            rec[i][0] = release - startNano;
            rec[i][1] = start - startNano;
            rec[i][2] = end - startNano;
            rec[i][3] = release - startNano + DEADLINE_NS;
            rec[i][4] = cpu;
        }
        stop = true;
        try (PrintWriter w = new PrintWriter(Files.newBufferedWriter(out.resolve("jobs.txt")))) {
            w.print("# index release_ns start_ns end_ns deadline_ns outcome cpu_ns\n");
            for (int i = 0; i < jobs; i++) {
                String outcome = rec[i][2] <= rec[i][3] ? "done" : "late";
                w.printf(Locale.ROOT, "%d %d %d %d %d %s %d%n", i, rec[i][0], rec[i][1], rec[i][2], rec[i][3], outcome, rec[i][4]);
            }
        }
        Files.write(out.resolve("clock.txt"), (startEpoch + " " + startNano + " " + ManagementFactory.getRuntimeMXBean().getStartTime() + "\n").getBytes("UTF-8"));
    }

    /** The job's work: spins on arithmetic until its own thread has used {@code cpuNs} of CPU. */
    static void compute(long cpuNs) {
        ThreadMXBean mx = ManagementFactory.getThreadMXBean();
        long end = mx.getCurrentThreadCpuTime() + cpuNs;
        double acc = 0;
        while (mx.getCurrentThreadCpuTime() < end) {
            for (int k = 0; k < 200; k++) {
                acc += Math.sin(k * 0.001 + acc) * 0.5;
            }
        }
        sink = acc;
    }

    /** About 150 MB/s of garbage with a 16 MB live set, so a small heap collects often. */
    static void allocate() {
        Object[] live = new Object[16 * 1024 / 4];
        long x = 7;
        long next = System.nanoTime();
        while (!stop) {
            for (int k = 0; k < 150; k++) {
                x ^= x << 13; x ^= x >>> 7; x ^= x << 17;
                live[(int) ((x >>> 1) % live.length)] = new byte[4096];
            }
            next += 1_000_000L;
            long sleep = next - System.nanoTime();
            if (sleep > 0) {
                try { Thread.sleep(sleep / 1_000_000, (int) (sleep % 1_000_000)); } catch (InterruptedException e) { return; }
            }
        }
    }
}
