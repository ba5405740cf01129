package org.jmclbench.workload.release;

import java.io.File;
import java.io.FileOutputStream;
import java.io.IOException;
import java.io.OutputStreamWriter;
import java.io.PrintStream;
import java.io.Writer;
import java.lang.management.ManagementFactory;
import java.nio.charset.StandardCharsets;
import java.util.LinkedHashMap;
import java.util.Map;
import org.jmclbench.workload.RunOptions;
import org.jmclbench.workload.data.Dataset;
import org.jmclbench.workload.data.Timeline;
import org.jmclbench.workload.load.AllocationNoise;
import org.jmclbench.workload.mcl.Localizer;
import org.jmclbench.workload.mcl.Localizers;
import org.jmclbench.workload.mcl.MclConfig;
import org.jmclbench.workload.record.JobRecords;

/**
 * A real-time (non-ideal) run: optional GC log, optional warm-up replay through the same
 * engine on a throwaway localizer and records, then the measured replay of the whole timeline
 * at its real release times under the run's policy, into the run's records.
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
    public static Map<String, Object> run(RunOptions options, Dataset dataset, Timeline timeline,
                                          Localizer localizer, JobRecords records, File runDir, PrintStream err)
            throws IOException {
        Map<String, Object> facts = new LinkedHashMap<>();
        facts.put("dispatcherPriority", ReleaseEngine.DISPATCHER_PRIORITY);
        facts.put("handlerPriority", ReleaseEngine.HANDLER_PRIORITY);
        facts.put("prioritiesApplied", prioritiesApplied());
        GcLog gcLog = options.gcLog ? GcLog.start(new File(runDir, "gc.log")) : null;
        AllocationNoise noise = null;
        try {
            if (gcLog != null && !gcLog.active()) {
                err.println("jmclbench: --gc-log: " + gcLog.status());
                writeNote(gcLog.file(), "# no GC log: " + gcLog.status() + "\n");
            }
            ThreadCpuClock cpuClock = ThreadCpuClock.probe();
            if (!cpuClock.usable()) {
                err.println("jmclbench: per-job CPU time: " + cpuClock.status() + "; cpu_ns is -1");
            }
            facts.put("cpuTime", cpuClock.status());
            facts.put("gcLog", gcLog == null ? null : gcLog.status());
            ReleaseSchedule schedule = ReleaseSchedule.of(timeline, options.timeScale);
            long spinNs = options.spinUs * 1000L;
            OverrunPolicy policy = OverrunPolicy.forName(options.policy.label);

            if (options.loadAllocMbPerS > 0) {
                noise = AllocationNoise.start(options.loadAllocMbPerS, options.loadAllocLiveMb);
            }
            int warmupEvents = options.warmupS > 0 ? schedule.countBefore(options.warmupS, options.timeScale) : 0;
            facts.put("warmupEvents", warmupEvents);
            if (options.warmupS > 0 && warmupEvents > 0) {
                Localizer throwaway = Localizers.create(options.mclConfig(), dataset.playground,
                        dataset.startX, dataset.startY, dataset.startTheta);
                JobRecords scratch = new JobRecords(timeline, records.cov != null);
                new ReleaseEngine(schedule.prefix(warmupEvents), OverrunPolicy.forName(options.policy.label),
                        new LocalizerJob(dataset, timeline, throwaway, scratch), scratch, cpuClock, spinNs).run();
            }

            records.clear();
            records.setInitialEstimate(localizer.estimateX(), localizer.estimateY(), localizer.estimateTheta());
            ReleaseEngine engine = new ReleaseEngine(schedule, policy,
                    new LocalizerJob(dataset, timeline, localizer, records), records, cpuClock, spinNs);
            ClockAnchor anchor = ClockAnchor.now();
            engine.run();
            records.durationNs = System.nanoTime() - engine.runStartNanoTime();
            facts.put("clock", anchor.forRunStart(engine.runStartNanoTime()));
            facts.put("allocatedBytes", engine.allocatedBytes() < 0 ? null : engine.allocatedBytes());
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
                Map<String, Object> load = new LinkedHashMap<>();
                load.put("allocMbPerS", options.loadAllocMbPerS);
                load.put("allocLiveMb", options.loadAllocLiveMb);
                load.put("allocatedBytes", noise.allocatedBytes());
                facts.put("loadAlloc", load);
            }
            if (gcLog != null) {
                gcLog.stop();
            }
        }
    }

    /**
     * Whether the Java thread priorities reach the OS scheduler: on Linux HotSpot ignores them
     * unless started with -XX:ThreadPriorityPolicy=1 (as root), and under SCHED_FIFO (chrt)
     * every thread inherits the same real-time priority anyway.
     */
    static boolean prioritiesApplied() {
        if (!System.getProperty("os.name", "").toLowerCase(java.util.Locale.ROOT).contains("linux")) {
            return true;
        }
        try {
            for (String a : ManagementFactory.getRuntimeMXBean().getInputArguments()) {
                if (a.equals("-XX:ThreadPriorityPolicy=1")) {
                    return true;
                }
            }
        } catch (RuntimeException | LinkageError e) {
            return false;
        }
        return false;
    }

    private static void writeNote(File f, String text) throws IOException {
        try (Writer w = new OutputStreamWriter(new FileOutputStream(f), StandardCharsets.UTF_8)) {
            w.write(text);
        }
    }
}
