package org.jmclbench.workload;

import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;

import org.jmclbench.workload.data.Dataset;
import org.jmclbench.core.timeline.Timeline;
import org.jmclbench.core.mcl.AbortSignal;
import org.jmclbench.core.mcl.Localizer;
import org.jmclbench.core.record.JobRecords;

/**
 * The "infinitely fast computer" (SPEC section 4): every event of the timeline processed in
 * order by the calling thread, as fast as possible, no release timing. The reference for
 * localisation accuracy. Each job's release and start are the moment the thread takes it;
 * deadlines are -1; every outcome is DONE. The loop allocates nothing.
 */
public final class IdealRun {
    private final Dataset dataset;
    private final Timeline timeline;
    private final Localizer localizer;
    private final JobRecords records;
    private final ThreadMXBean threads;
    private final boolean cpuTime;
    private final double[] covariance = new double[6];

    public IdealRun(Dataset dataset, Timeline timeline, Localizer localizer, JobRecords records) {
        this.dataset = dataset;
        this.timeline = timeline;
        this.localizer = localizer;
        this.records = records;
        threads = ManagementFactory.getThreadMXBean();
        cpuTime = threads.isCurrentThreadCpuTimeSupported() && threads.isThreadCpuTimeEnabled();
        // First calls resolve and load what the clocks need: before the measured window.
        if (cpuTime) {
            threads.getCurrentThreadCpuTime();
        }
        System.nanoTime();
    }

    /** Replays the whole timeline into the records. */
    public static void run(Dataset dataset, Timeline timeline, Localizer localizer, JobRecords records) {
        new IdealRun(dataset, timeline, localizer, records).run();
    }

    /** Replays the events up to warmupS seconds on a throwaway localizer, so that the JIT has compiled the jobs. */
    public static void warmup(Dataset dataset, Timeline timeline, Localizer throwaway, double warmupS) {
        for (int k = 0; k < timeline.size() && timeline.time(k) <= warmupS; k++) {
            job(dataset, timeline, throwaway, k);
        }
    }

    /** Replays every event into the records. */
    public void run() {
        JobRecords r = records;
        r.clear();
        r.setInitialEstimate(localizer.estimateX(), localizer.estimateY(), localizer.estimateTheta());
        boolean cov = r.cov != null;
        long t0 = System.nanoTime();
        for (int k = 0; k < timeline.size(); k++) {
            long cpu0 = cpuTime ? threads.getCurrentThreadCpuTime() : -1;
            long start = System.nanoTime() - t0;
            job(dataset, timeline, localizer, k);
            long end = System.nanoTime() - t0;
            long cpu1 = cpuTime ? threads.getCurrentThreadCpuTime() : -1;
            r.releaseNs[k] = start;
            r.startNs[k] = start;
            r.endNs[k] = end;
            r.cpuNs[k] = cpuTime ? cpu1 - cpu0 : -1;
            r.outcome[k] = JobRecords.DONE;
            r.estX[k] = localizer.estimateX();
            r.estY[k] = localizer.estimateY();
            r.estTheta[k] = localizer.estimateTheta();
            if (cov && timeline.task(k) == Timeline.UPDATE) {
                localizer.covariance(covariance);
                System.arraycopy(covariance, 0, r.cov, 6 * k, 6);
            }
        }
        r.durationNs = System.nanoTime() - t0;
    }

    private static void job(Dataset d, Timeline t, Localizer l, int k) {
        int i = t.taskIndex(k);
        if (t.task(k) == Timeline.PREDICT) {
            l.predict(d.odoDx[i], d.odoDy[i], d.odoDtheta[i], AbortSignal.NEVER);
        } else {
            l.update(d.laserAngle[i], AbortSignal.NEVER);
        }
    }
}
