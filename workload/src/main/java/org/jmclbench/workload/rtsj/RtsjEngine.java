package org.jmclbench.workload.rtsj;

import java.io.IOException;
import java.util.Collections;

import javax.realtime.PriorityScheduler;

import org.jmclbench.core.mcl.Localizer;
import org.jmclbench.core.policy.OverrunPolicy;
import org.jmclbench.core.record.JobRecords;
import org.jmclbench.core.timeline.Timeline;
import org.jmclbench.workload.BadInputException;
import org.jmclbench.workload.RunFailure;
import org.jmclbench.workload.RunOptions;
import org.jmclbench.workload.data.Dataset;
import org.jmclbench.workload.engine.Engine;
import org.jmclbench.workload.engine.EngineInput;
import org.jmclbench.workload.engine.EngineResult;
import org.jmclbench.workload.output.HeapUse;
import org.jmclbench.workload.release.AbortRehearsal;
import org.jmclbench.workload.release.JavaSeEngine;
import org.jmclbench.workload.release.LocalizerJob;
import org.jmclbench.workload.release.ReleaseSchedule;
import org.jmclbench.workload.shim.CpuClock;
import org.jmclbench.workload.shim.RuntimeShim;

/**
 * {@code --engine rtsj}: the thesis's RTSJ program on rtsj-compat's RTSJ layer ({@link RtsjReplay}),
 * with terminate by asynchronous transfer of control in the design {@code --rtsj-design} names
 * ({@link RtsjDesign}); the job code's delivery points are woven at build time (rtsj-weaver).
 * Its one memory area is the heap. Per-job CPU time is the shim's clock ({@link RuntimeShim#cpuClock}):
 * the javase engine's on a JVM, none on an RTSJ VM.
 */
public final class RtsjEngine implements Engine {
    /** Events of the class-loading replay that runs before the measured one when there is no warm-up. */
    private static final int PRELOAD_EVENTS = 4;
    /** Beyond the replay's last release, how long the engine waits for the jobs before it calls the run hung. */
    private static final long HANG_MARGIN_NS = 120_000_000_000L;

    @Override
    public String name() {
        return "rtsj";
    }

    /** The design is part of the runtime name: the two designs' runs never share a folder. */
    @Override
    public String runtimeName(String jvmName, RunOptions options) {
        return jvmName + "-rtsj-" + options.rtsjDesign.label;
    }

    @Override
    public void checkOptions(RunOptions o) throws BadInputException {
        JavaSeEngine.checkHeapOptions(name(), o);
        JavaSeEngine.checkReleaseLoopOptions(name(), o);
    }

    @Override
    public EngineResult run(EngineInput in) throws IOException, RunFailure {
        RunOptions o = in.options;
        Dataset d = in.dataset;
        Timeline timeline = d.timeline();
        ReleaseSchedule schedule = ReleaseSchedule.of(timeline, o.timeScale);
        RtsjFacts facts = new RtsjFacts();
        facts.design = o.rtsjDesign;
        facts.dispatcherPriority = PriorityScheduler.instance().getMaxPriority();
        facts.handlerPriority = facts.dispatcherPriority - 1;
        facts.prioritiesApplied = RuntimeShim.get().prioritiesApplied();
        int warmup = o.warmupS > 0 ? schedule.countBefore(o.warmupS, o.timeScale) : 0;
        facts.warmupEvents = warmup;
        // probed before any replay, so that the warm-up and class-loading replays read it too
        CpuClock cpuClock = RuntimeShim.get().cpuClock(o.cpuTime);
        cpuClock.warnIfNotUsable(o.cpuTime, in.err);
        facts.cpuTime = cpuClock.status();
        try {
            if (o.policy == OverrunPolicy.TERMINATE) {
                // before the replays below compile the job code: code compiled while no AIE was
                // ever delivered takes each first delivery through a deoptimisation
                RuntimeShim.get().beforeAborts();
            }
            if (warmup > 0) {
                replay(in, schedule.prefix(warmup), o.policy, cpuClock);
            } else {
                // Class loading out of the measured window: queue runs every job of the first
                // events, then the run's own policy loads what only its path touches.
                ReleaseSchedule first = schedule.prefix(Math.min(PRELOAD_EVENTS, schedule.size()));
                replay(in, first, OverrunPolicy.QUEUE, cpuClock);
                if (o.policy != OverrunPolicy.QUEUE) {
                    replay(in, first, o.policy, cpuClock);
                }
            }
            if (o.policy == OverrunPolicy.TERMINATE) {
                rehearseAborts(in, cpuClock);
            }
            JobRecords records = new JobRecords(timeline, o.covariance);
            Localizer localizer = in.newLocalizer();
            records.setInitialEstimate(localizer.estimateX(), localizer.estimateY(), localizer.estimateTheta());
            HeapUse heap = HeapUse.begin();
            RtsjReplay replay = new RtsjReplay(schedule, o.policy, o.rtsjDesign,
                    new LocalizerJob(d, timeline, localizer, records), records, cpuClock);
            replay.run(hangNs(schedule));
            records.durationNs = replay.elapsedNs();
            return new EngineResult(records, Collections.singletonList(heap.end(null, records)), facts);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new RunFailure("the rtsj run was interrupted");
        }
    }

    /** A replay on a throwaway localizer and records (class loading, warm-up). */
    private static void replay(EngineInput in, ReleaseSchedule schedule, OverrunPolicy policy, CpuClock cpuClock)
            throws RunFailure, InterruptedException {
        Timeline timeline = in.dataset.timeline();
        JobRecords scratch = new JobRecords(timeline, in.options.covariance);
        new RtsjReplay(schedule, policy, in.options.rtsjDesign,
                new LocalizerJob(in.dataset, timeline, in.newLocalizer(), scratch), scratch, cpuClock)
                .run(hangNs(schedule));
    }

    /**
     * terminate: two AIEs fired at jobs that only poll ({@link AbortRehearsal}), before the
     * measured window, so that the first aborts measured do not pay for loading and resolving the
     * ATC code (the class loading that {@link #PRELOAD_EVENTS} keeps out of the window for the
     * other paths).
     */
    private static void rehearseAborts(EngineInput in, CpuClock cpuClock) throws RunFailure, InterruptedException {
        ReleaseSchedule schedule = AbortRehearsal.schedule();
        new RtsjReplay(schedule, OverrunPolicy.TERMINATE, in.options.rtsjDesign, AbortRehearsal.job(), AbortRehearsal.records(),
                cpuClock).run(hangNs(schedule));
    }

    private static long hangNs(ReleaseSchedule schedule) {
        return (schedule.size() == 0 ? 0 : schedule.releaseNs(schedule.size() - 1)) + HANG_MARGIN_NS;
    }
}
