package org.jmclbench.bench;

import java.io.File;
import java.lang.management.ManagementFactory;
import java.util.Locale;
import org.jmclbench.workload.data.Dataset;
import org.jmclbench.workload.data.DatasetReader;
import org.jmclbench.core.mcl.AbortSignal;
import org.jmclbench.core.mcl.Localizer;
import org.jmclbench.workload.mcl.Localizers;
import org.jmclbench.core.mcl.MclConfig;

/**
 * Exact bytes allocated per job by the calling thread, from the JVM's per-thread allocation
 * counter, over warm jobs replayed as {@link KernelBenchmark} replays them. JMH's
 * gc.alloc.rate.norm adds its own per-iteration bookkeeping spread over the jobs; this count
 * has none, so it can say "zero" exactly.
 *
 * <p>Usage: {@code java -cp benchmarks.jar org.jmclbench.bench.AllocationCheck DATASET N[,N..]};
 * prints {@code job particles memory bytes_per_job} lines ({@code n/a} where the JVM has no
 * such counter).
 */
public final class AllocationCheck {
    private static final int WARM_JOBS = 1000;
    private static final int MEASURED_JOBS = 200;

    private AllocationCheck() {
    }

    public static void main(String[] args) throws Exception {
        if (args.length != 2) {
            System.err.println("usage: AllocationCheck DATASET_DIR N[,N...]");
            System.exit(2);
        }
        Dataset d = DatasetReader.readFolder(new File(args[0]));
        System.out.println("# job particles memory bytes_per_job (" + MEASURED_JOBS + " jobs after " + WARM_JOBS
                + " warm-up jobs)");
        for (String job : new String[] {"predict", "update"}) {
            for (String n : args[1].split(",")) {
                for (MclConfig.Memory m : MclConfig.Memory.values()) {
                    double b = bytesPerJob(d, Integer.parseInt(n.trim()), m, job.equals("update"));
                    System.out.println(job + " " + n.trim() + " " + m.name().toLowerCase(Locale.ROOT) + " "
                            + (Double.isNaN(b) ? "n/a" : String.format(Locale.ROOT, "%.1f", b)));
                }
            }
        }
    }

    /** Bytes per warm job of the given kind, or NaN when this JVM has no per-thread allocation counter. */
    static double bytesPerJob(Dataset d, int particles, MclConfig.Memory memory, boolean update) {
        java.lang.management.ThreadMXBean mx = ManagementFactory.getThreadMXBean();
        if (!(mx instanceof com.sun.management.ThreadMXBean)) {
            return Double.NaN;
        }
        com.sun.management.ThreadMXBean tmx = (com.sun.management.ThreadMXBean) mx;
        if (!tmx.isThreadAllocatedMemorySupported()) {
            return Double.NaN;
        }
        tmx.setThreadAllocatedMemoryEnabled(true);
        MclConfig config = MclConfig.builder().particles(particles).memory(memory).seed(1).build();
        Localizer loc = Localizers.create(config, d.playground, d.startX, d.startY, d.startTheta);
        long tid = Thread.currentThread().getId();
        int k = 0;
        for (int i = 0; i < WARM_JOBS; i++) {
            k = job(loc, d, update, k);
        }
        // The counter read itself may allocate: measure it with nothing between two reads.
        long c0 = tmx.getThreadAllocatedBytes(tid);
        long c1 = tmx.getThreadAllocatedBytes(tid);
        long before = tmx.getThreadAllocatedBytes(tid);
        for (int i = 0; i < MEASURED_JOBS; i++) {
            k = job(loc, d, update, k);
        }
        long after = tmx.getThreadAllocatedBytes(tid);
        return Math.max(0, after - before - (c1 - c0)) / (double) MEASURED_JOBS;
    }

    private static int job(Localizer loc, Dataset d, boolean update, int k) {
        if (update) {
            loc.update(d.laserAngle[k], AbortSignal.NEVER);
            return k + 1 == d.laserAngle.length ? 0 : k + 1;
        }
        loc.predict(d.odoDx[k], d.odoDy[k], d.odoDtheta[k], AbortSignal.NEVER);
        return k + 1 == d.odoDx.length ? 0 : k + 1;
    }
}
