package org.jmclbench.workload.release;

import java.io.File;
import java.io.FileOutputStream;
import java.io.IOException;
import java.io.OutputStreamWriter;
import java.io.PrintStream;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import org.jmclbench.workload.RunOptions;
import org.jmclbench.workload.shim.RuntimeShim;
import org.jmclbench.workload.data.Dataset;
import org.jmclbench.core.timeline.Timeline;
import org.jmclbench.workload.load.AllocationNoise;
import org.jmclbench.core.mcl.AbortSignal;
import org.jmclbench.core.mcl.Localizer;
import org.jmclbench.workload.mcl.Localizers;
import org.jmclbench.core.mcl.MclConfig;
import org.jmclbench.core.policy.OverrunPolicy;
import org.jmclbench.core.record.JobRecords;

/**
 * A real-time (non-ideal) run: optional GC log, under terminate an {@link AbortRehearsal},
 * optional warm-up replay through the same engine on a throwaway localizer and records, then the
 * measured replay of the whole timeline at its real release times under the run's policy, into
 * the run's records.
 */
public final class RealTimeRun {
    private RealTimeRun() {
    }

    /**
     * Runs the test; on return every event of {@code records} is done, late, skipped or
     * terminated, and the GC log (with {@code --gc-log}) is closed as {@code runDir/gc.log}.
     *
     * @return facts about the engine for summary.json's {@code "engine"} object
     *
     * @param runDir the (partial) run folder, for the GC log
     * @param err    where the one-line notes about the runtime go (before the measured window)
     */
    public static JavaSeFacts run(RunOptions options, Dataset dataset, Timeline timeline,
                                          Localizer localizer, JobRecords records, File runDir, PrintStream err)
            throws IOException {
        JavaSeFacts facts = new JavaSeFacts();
        // one rule for every engine on this JVM: the SCJ layer's (HotSpot ignores priorities on Linux without
        // -XX:ThreadPriorityPolicy=1, and under chrt every thread inherits one priority anyway)
        facts.prioritiesApplied = RuntimeShim.get().prioritiesApplied();
        GcLog gcLog = GcLog.startIfAsked(options.gcLog, runDir, err);
        AllocationNoise noise = null;
        try {
            if (gcLog != null && !gcLog.active()) {
                writeNote(gcLog.file(), "# no GC log: " + gcLog.status() + "\n");
            }
            ThreadCpuClock cpuClock = ThreadCpuClock.forRun(options.cpuTime);
            cpuClock.warnIfNotUsable(options.cpuTime, err);
            facts.cpuTime = cpuClock.status();
            facts.gcLog = gcLog == null ? null : gcLog.status();
            ReleaseSchedule schedule = ReleaseSchedule.of(timeline, options.timeScale);
            long spinNs = options.spinUs * 1000L;
            PolicyGate policy = PolicyGate.of(options.policy);

            if (options.loadAllocMbPerS > 0) {
                noise = AllocationNoise.start(options.loadAllocMbPerS, options.loadAllocLiveMb);
            }
            if (options.policy == OverrunPolicy.TERMINATE) {
                // first: before any replay compiles the job's loops with the gate's answer inlined
                new ReleaseEngine(AbortRehearsal.schedule(), PolicyGate.of(OverrunPolicy.TERMINATE), AbortRehearsal.job(),
                        AbortRehearsal.records(), cpuClock, 0).run();
            }
            int warmupEvents = options.warmupS > 0 ? schedule.countBefore(options.warmupS, options.timeScale) : 0;
            facts.warmupEvents = warmupEvents;
            if (options.warmupS > 0 && warmupEvents > 0) {
                Localizer throwaway = Localizers.create(options.mclConfig(), dataset.playground,
                        dataset.startX, dataset.startY, dataset.startTheta);
                JobRecords scratch = new JobRecords(timeline, records.cov != null);
                new ReleaseEngine(schedule.prefix(warmupEvents), PolicyGate.of(options.policy),
                        new LocalizerJob(dataset, timeline, throwaway, scratch), scratch, cpuClock, spinNs).run();
            }

            if (warmupEvents == 0) {
                preload(options, dataset, timeline, records.cov != null, cpuClock);
            }

            records.clear();
            records.setInitialEstimate(localizer.estimateX(), localizer.estimateY(), localizer.estimateTheta());
            ReleaseEngine engine = new ReleaseEngine(schedule, policy,
                    new LocalizerJob(dataset, timeline, localizer, records), records, cpuClock, spinNs);
            ClockAnchor anchor = ClockAnchor.now();
            engine.run();
            records.durationNs = System.nanoTime() - engine.runStartNanoTime();
            anchor.stampRunStart(facts, engine.runStartNanoTime());
            facts.allocatedBytes = engine.allocatedBytes() < 0 ? null : Long.valueOf(engine.allocatedBytes());
            if (options.memory == MclConfig.Memory.PREALLOCATED && engine.allocatedBytes() > 0) {
                err.println("jmclbench: warning: the measured window allocated " + engine.allocatedBytes()
                        + " bytes on the engine's threads (expected none)");
            }
            return facts;
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IllegalStateException("the run was interrupted", e);
        } finally {
            if (noise != null) {
                noise.stop();
                facts.loadAlloc = noise;
            }
            if (gcLog != null) {
                gcLog.stop();
            }
        }
    }

    /**
     * Without a warm-up, still keeps class loading (jar reads and allocation on the handler
     * threads, some 20 KB) out of the measured window: one predict and one update on a
     * throwaway localizer, and a two-event replay of the engine with an empty job. Only classes
     * are loaded and initialised; the code stays as cold as the runtime leaves it (no JIT warm-up).
     */
    private static void preload(RunOptions options, Dataset dataset, Timeline timeline, boolean covariance,
                                ThreadCpuClock cpuClock) throws InterruptedException {
        Localizer throwaway = Localizers.create(options.mclConfig(), dataset.playground,
                dataset.startX, dataset.startY, dataset.startTheta);
        JobRecords scratch = new JobRecords(timeline, covariance);
        LocalizerJob job = new LocalizerJob(dataset, timeline, throwaway, scratch);
        boolean predicted = false;
        boolean updated = false;
        for (int k = 0; k < timeline.size() && !(predicted && updated); k++) {
            if (timeline.task(k) == Timeline.PREDICT && !predicted) {
                predicted = job.run(k, AbortSignal.NEVER);
            } else if (timeline.task(k) == Timeline.UPDATE && !updated) {
                updated = job.run(k, AbortSignal.NEVER);
            }
        }
        int n = Math.min(2, timeline.size());
        long[] release = new long[n];
        long[] deadline = new long[n];
        int[] task = new int[n];
        for (int k = 0; k < n; k++) {
            deadline[k] = Long.MAX_VALUE;
            task[k] = k % 2;
        }
        new ReleaseEngine(ReleaseSchedule.of(release, deadline, task), PolicyGate.of(options.policy),
                (k, abort) -> abort.abortRequested() || true, scratch, cpuClock, 0).run();
    }

    private static void writeNote(File f, String text) throws IOException {
        try (Writer w = new OutputStreamWriter(new FileOutputStream(f), StandardCharsets.UTF_8)) {
            w.write(text);
        }
    }
}
