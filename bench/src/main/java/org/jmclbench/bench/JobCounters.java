package org.jmclbench.bench;

import java.io.File;
import java.lang.management.ManagementFactory;
import java.util.Locale;
import org.jmclbench.workload.data.Dataset;
import org.jmclbench.workload.data.DatasetReader;
import org.jmclbench.workload.mcl.AbortSignal;
import org.jmclbench.workload.mcl.Localizer;
import org.jmclbench.workload.mcl.Localizers;
import org.jmclbench.workload.mcl.MclConfig;

/**
 * Per-job counters of the calling thread over warm jobs replayed as {@link KernelBenchmark}
 * replays them: the bytes it allocates (exact, unlike JMH's gc.alloc.rate.norm, which adds
 * JMH's own per-iteration bookkeeping) and the CPU time it spends (which, unlike wall time,
 * excludes the time the thread waited for a CPU on a busy machine).
 *
 * <p>Usage: {@code java -cp benchmarks.jar org.jmclbench.bench.JobCounters DATASET N[,N..]};
 * prints {@code job particles memory bytes_per_job cpu_ns_per_job} lines ({@code n/a} where
 * the JVM has no such counter).
 */
public final class JobCounters {
    private static final int WARM_JOBS = 1000;
    /** Warm-up lasts at least this long too, as JMH's 3 x 1 s, so the JIT finishes even on a busy machine. */
    private static final long WARM_NS = 3_000_000_000L;
    private static final int ALLOCATION_JOBS = 200;
    private static final long CPU_BUDGET_NS = 1_000_000_000L;

    private final Localizer localizer;
    private final Dataset data;
    private final boolean update;
    private final long warmNs;
    private int next;

    private JobCounters(Dataset d, int particles, MclConfig.Memory memory, boolean update, long warmNs) {
        this.warmNs = warmNs;
        MclConfig config = MclConfig.builder().particles(particles).memory(memory).seed(1).build();
        this.localizer = Localizers.create(config, d.playground, d.startX, d.startY, d.startTheta);
        this.data = d;
        this.update = update;
    }

    public static void main(String[] args) throws Exception {
        if (args.length != 2) {
            System.err.println("usage: JobCounters DATASET_DIR N[,N...]");
            System.exit(2);
        }
        Dataset d = DatasetReader.readFolder(new File(args[0]));
        System.out.println("# job particles memory bytes_per_job cpu_ns_per_job (after " + WARM_JOBS
                + " warm-up jobs and at least 3 s; bytes over " + ALLOCATION_JOBS + " jobs, CPU over about 1 s of jobs)");
        for (String job : new String[] {"predict", "update"}) {
            for (String n : args[1].split(",")) {
                for (MclConfig.Memory m : MclConfig.Memory.values()) {
                    JobCounters c = new JobCounters(d, Integer.parseInt(n.trim()), m, job.equals("update"), WARM_NS);
                    c.warm();
                    double bytes = c.bytesPerJob();
                    double cpu = c.cpuNsPerJob();
                    System.out.println(job + " " + n.trim() + " " + m.name().toLowerCase(Locale.ROOT) + " "
                            + format(bytes, "%.1f") + " " + format(cpu, "%.0f"));
                }
            }
        }
    }

    private static String format(double v, String f) {
        return Double.isNaN(v) ? "n/a" : String.format(Locale.ROOT, f, v);
    }

    /**
     * Bytes per job of the given kind after {@link #WARM_JOBS} jobs (no minimum warm-up time:
     * the count does not depend on the JIT), or NaN when this JVM has no per-thread allocation counter.
     */
    static double bytesPerJob(Dataset d, int particles, MclConfig.Memory memory, boolean update) {
        JobCounters c = new JobCounters(d, particles, memory, update, 0);
        c.warm();
        return c.bytesPerJob();
    }

    private void warm() {
        long start = System.nanoTime();
        for (int i = 0; i < WARM_JOBS || System.nanoTime() - start < warmNs; i++) {
            job();
        }
    }

    private double bytesPerJob() {
        com.sun.management.ThreadMXBean tmx = allocationCounter();
        if (tmx == null) {
            return Double.NaN;
        }
        long tid = Thread.currentThread().getId();
        // The counter read itself may allocate: measure it with nothing between two reads.
        long c0 = tmx.getThreadAllocatedBytes(tid);
        long c1 = tmx.getThreadAllocatedBytes(tid);
        long before = tmx.getThreadAllocatedBytes(tid);
        for (int i = 0; i < ALLOCATION_JOBS; i++) {
            job();
        }
        long after = tmx.getThreadAllocatedBytes(tid);
        return Math.max(0, after - before - (c1 - c0)) / (double) ALLOCATION_JOBS;
    }

    private double cpuNsPerJob() {
        java.lang.management.ThreadMXBean mx = ManagementFactory.getThreadMXBean();
        if (!mx.isCurrentThreadCpuTimeSupported()) {
            return Double.NaN;
        }
        long start = mx.getCurrentThreadCpuTime();
        long now;
        long jobs = 0;
        do {
            job();
            jobs++;
            now = mx.getCurrentThreadCpuTime();
        } while (now - start < CPU_BUDGET_NS);
        return (now - start) / (double) jobs;
    }

    private static com.sun.management.ThreadMXBean allocationCounter() {
        java.lang.management.ThreadMXBean mx = ManagementFactory.getThreadMXBean();
        if (!(mx instanceof com.sun.management.ThreadMXBean)) {
            return null;
        }
        com.sun.management.ThreadMXBean tmx = (com.sun.management.ThreadMXBean) mx;
        if (!tmx.isThreadAllocatedMemorySupported()) {
            return null;
        }
        tmx.setThreadAllocatedMemoryEnabled(true);
        return tmx;
    }

    private void job() {
        int k = next;
        if (update) {
            next = k + 1 == data.laserAngle.length ? 0 : k + 1;
            localizer.update(data.laserAngle[k], AbortSignal.NEVER);
        } else {
            next = k + 1 == data.odoDx.length ? 0 : k + 1;
            localizer.predict(data.odoDx[k], data.odoDy[k], data.odoDtheta[k], AbortSignal.NEVER);
        }
    }
}
