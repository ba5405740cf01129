package org.jmclbench.workload.rtsj;

import org.jmclbench.workload.engine.EngineFacts;
import org.jmclbench.workload.output.Json;
import org.jmclbench.workload.output.RunWriter;
import org.jmclbench.workload.record.Stats;

/** summary.json's {@code engine} object of an rtsj run (docs/FORMATS.md section 4). */
final class RtsjFacts implements EngineFacts {
    RtsjDesign design;
    int warmupEvents;
    int dispatcherPriority;
    int handlerPriority;
    boolean prioritiesApplied;
    /** Jobs whose abort was requested (an AIE fired at them) and ended; of those, the ones that completed anyway. */
    int abortsRequested;
    int abortsDeferredToCompletion;
    /** Abort latency, ns from the AIE's fire to the end of the job it was fired at. */
    Stats abortLatency = Stats.empty();

    @Override
    public void writeTo(Json j) {
        j.name("design").value(design.label);
        j.name("warmupEvents").value(warmupEvents);
        j.name("dispatcherPriority").value(dispatcherPriority);
        j.name("handlerPriority").value(handlerPriority);
        j.name("prioritiesApplied").value(prioritiesApplied);
        j.name("abortsRequested").value(abortsRequested);
        j.name("abortsDeferredToCompletion").value(abortsDeferredToCompletion);
        j.name("abortLatencyNs");
        RunWriter.writeStats(j, abortLatency);
    }
}
