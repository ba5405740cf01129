package org.jmclbench.workload.release;

import org.jmclbench.workload.engine.EngineFacts;
import org.jmclbench.workload.load.AllocationNoise;
import org.jmclbench.workload.output.Json;

/** summary.json's {@code engine} object of a javase run (docs/FORMATS.md section 4), filled by {@link RealTimeRun}. */
public final class JavaSeFacts implements EngineFacts {
    /** Whether the dispatcher's and handlers' Java priorities reached the OS scheduler. */
    boolean prioritiesApplied;
    /** How per-job CPU time was obtained, or why it was not. */
    String cpuTime;
    /** The GC log's status, or null without {@code --gc-log}. */
    String gcLog;
    /** Events replayed before the measured window. */
    int warmupEvents;
    /** The measured run's time 0 on the wall clock, on nanoTime, and the JVM's start (ms), for the tooling's timelines. */
    long runStartEpochNs;
    long runStartNanoTime;
    long jvmStartEpochMs = -1;
    /** Bytes the engine's threads allocated in the measured window; null when the JVM cannot tell. */
    Long allocatedBytes;
    /** The allocation load, stopped, when one ran ({@code --load-alloc MBPS,LIVEMB}); else null. */
    AllocationNoise loadAlloc;

    /** Bytes allocated on the engine's threads in the measured window, or null (unknown). */
    public Long allocatedBytes() {
        return allocatedBytes;
    }

    /** The events replayed before the measured window. */
    public int warmupEvents() {
        return warmupEvents;
    }

    @Override
    public void writeTo(Json j) {
        j.name("dispatcherPriority").value(ReleaseEngine.DISPATCHER_PRIORITY);
        j.name("handlerPriority").value(ReleaseEngine.HANDLER_PRIORITY);
        j.name("prioritiesApplied").value(prioritiesApplied);
        j.name("cpuTime").value(cpuTime);
        j.name("gcLog").value(gcLog);
        j.name("warmupEvents").value(warmupEvents);
        j.name("clock").beginObject();
        j.name("runStartEpochNs").value(runStartEpochNs);
        j.name("runStartNanoTime").value(runStartNanoTime);
        j.name("jvmStartEpochMs").value(jvmStartEpochMs);
        j.endObject();
        j.name("allocatedBytes").any(allocatedBytes);
        if (loadAlloc != null) {
            loadAlloc.writeFacts(j);
        }
    }
}
