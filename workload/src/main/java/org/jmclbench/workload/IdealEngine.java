package org.jmclbench.workload;

import java.util.Collections;

import org.jmclbench.core.mcl.Localizer;
import org.jmclbench.core.record.JobRecords;
import org.jmclbench.core.timeline.Timeline;
import org.jmclbench.workload.data.Dataset;
import org.jmclbench.workload.engine.Engine;
import org.jmclbench.workload.engine.EngineFacts;
import org.jmclbench.workload.engine.EngineInput;
import org.jmclbench.workload.engine.EngineResult;
import org.jmclbench.workload.load.AllocationNoise;
import org.jmclbench.workload.output.HeapUse;
import org.jmclbench.workload.release.GcLog;
import org.jmclbench.workload.release.ThreadCpuClock;

/**
 * {@code --ideal}, whatever {@code --engine} names: the {@link IdealRun} on the calling thread,
 * the reference for localisation accuracy. Its one memory area is the heap. With
 * {@code --load-alloc} the allocation load runs beside it as beside a real-time run, since the
 * run records that load among its parameters.
 */
public final class IdealEngine implements Engine {

    @Override
    public String name() {
        return "ideal";
    }

    /**
     * Refuses what an ideal run cannot apply, whatever the engine: a spin before each release (it
     * has no releases) and SCJ memory areas (its one area is the heap); given, they were recorded
     * in summary.json's parameters as if they had been applied. The rest is checked with the
     * engine it is asked of. The C baseline refuses --ideal --spin-us alike.
     */
    @Override
    public void checkOptions(RunOptions options) throws BadInputException {
        if (options.spinUs > 0) {
            throw BadInputException.ofOption("--spin-us", "an ideal run has no releases to spin before (--ideal)");
        }
        if (!options.areaSizes.isEmpty()) {
            throw BadInputException.ofOption("--area-size", "an ideal run has no SCJ memory areas (--ideal)");
        }
    }

    @Override
    public EngineResult run(EngineInput in) {
        RunOptions options = in.options;
        Dataset dataset = in.dataset;
        Timeline timeline = dataset.timeline();
        JobRecords records = new JobRecords(timeline, options.covariance);
        AllocationNoise noise = options.loadAllocMbPerS > 0
                ? AllocationNoise.start(options.loadAllocMbPerS, options.loadAllocLiveMb) : null;
        HeapUse heap;
        try {
            if (options.warmupS > 0) {
                IdealRun.warmup(dataset, timeline, in.newLocalizer(), options.warmupS);
            }
            Localizer localizer = in.newLocalizer();
            ThreadCpuClock cpuClock = ThreadCpuClock.forRun(options.cpuTime);
            heap = HeapUse.begin();
            // The GC log covers the measured replay only, as in real-time runs.
            GcLog gcLog = GcLog.startIfAsked(options.gcLog, in.folder, in.err);
            try {
                IdealRun.run(dataset, timeline, localizer, records, cpuClock);
            } finally {
                if (gcLog != null) {
                    gcLog.stop();
                }
            }
        } finally {
            if (noise != null) {
                noise.stop();
            }
        }
        EngineFacts facts = noise == null ? EngineFacts.NONE : noise::writeFacts;
        return new EngineResult(records, Collections.singletonList(heap.end(null, records)), facts);
    }
}
