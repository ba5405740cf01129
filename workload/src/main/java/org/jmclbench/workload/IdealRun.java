package org.jmclbench.workload;

import org.jmclbench.workload.data.Dataset;
import org.jmclbench.core.timeline.Timeline;
import org.jmclbench.core.mcl.AbortSignal;
import org.jmclbench.core.mcl.Localizer;
import org.jmclbench.core.record.JobRecords;
import org.jmclbench.workload.release.JobRecorder;
import org.jmclbench.workload.release.LocalizerJob;
import org.jmclbench.workload.release.ThreadCpuClock;

/**
 * The "infinitely fast computer" (SPEC section 4): every event of the timeline processed in
 * order by the calling thread, as fast as possible, no release timing. The reference for
 * localisation accuracy. Each job's release and start are the moment the thread takes it;
 * deadlines are -1; every outcome is DONE. The loop allocates nothing.
 */
public final class IdealRun {
    private final Timeline timeline;
    private final Localizer localizer;
    private final JobRecords records;
    private final JobRecorder recorder;
    private final LocalizerJob job;

    /**
     * @param cpuClock the per-job CPU clock: {@link ThreadCpuClock#probe()}, which also makes its
     *                 first calls before the measured window, or a disabled one ({@code --no-cpu-time})
     */
    public IdealRun(Dataset dataset, Timeline timeline, Localizer localizer, JobRecords records,
                    ThreadCpuClock cpuClock) {
        this.timeline = timeline;
        this.localizer = localizer;
        this.records = records;
        this.recorder = new JobRecorder(records, cpuClock, 0);
        this.job = new LocalizerJob(dataset, timeline, localizer, records);
        System.nanoTime(); // first call resolves what the clock needs: before the measured window
    }

    /** Replays the whole timeline into the records. */
    public static void run(Dataset dataset, Timeline timeline, Localizer localizer, JobRecords records,
                           ThreadCpuClock cpuClock) {
        new IdealRun(dataset, timeline, localizer, records, cpuClock).run();
    }

    /** Replays the events up to warmupS seconds on a throwaway localizer, so that the JIT has compiled the jobs. */
    public static void warmup(Dataset dataset, Timeline timeline, Localizer throwaway, double warmupS) {
        LocalizerJob job = new LocalizerJob(dataset, timeline, throwaway, null); // steps only: the warm-up records nothing
        for (int k = 0; k < timeline.size() && timeline.time(k) <= warmupS; k++) {
            job.step(k, AbortSignal.NEVER);
        }
    }

    /** Replays every event into the records. */
    public void run() {
        JobRecords r = records;
        r.clear();
        r.setInitialEstimate(localizer.estimateX(), localizer.estimateY(), localizer.estimateTheta());
        long t0 = System.nanoTime();
        JobRecorder recorder = this.recorder;
        LocalizerJob job = this.job;
        recorder.runStart(t0);
        for (int k = 0; k < timeline.size(); k++) {
            recorder.start();
            job.step(k, AbortSignal.NEVER);
            recorder.end();
            recorder.record(k, true, -1); // deadline -1: done
            r.releaseNs[k] = r.startNs[k];
            job.commitEstimate(k); // after the end: the ideal job's time is the step alone
        }
        r.durationNs = System.nanoTime() - t0;
    }
}
