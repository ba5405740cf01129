package org.jmclbench.workload.rtsj;

import org.jmclbench.workload.engine.EngineFacts;
import org.jmclbench.workload.output.Json;

/** summary.json's {@code engine} object of an rtsj run (docs/FORMATS.md section 4). */
final class RtsjFacts implements EngineFacts {
    RtsjDesign design;
    int warmupEvents;
    int dispatcherPriority;
    int handlerPriority;
    boolean prioritiesApplied;
    /** How per-job CPU time was obtained, or why it was not (the shim's clock's status). */
    String cpuTime;

    @Override
    public void writeTo(Json j) {
        j.name("design").value(design.label);
        j.name("warmupEvents").value(warmupEvents);
        j.name("dispatcherPriority").value(dispatcherPriority);
        j.name("handlerPriority").value(handlerPriority);
        j.name("prioritiesApplied").value(prioritiesApplied);
        j.name("cpuTime").value(cpuTime);
    }
}
