package org.jmclbench.workload.release;

import java.io.IOException;
import java.util.Collections;

import org.jmclbench.core.mcl.Localizer;
import org.jmclbench.core.mcl.MclConfig;
import org.jmclbench.core.record.JobRecords;
import org.jmclbench.core.timeline.Timeline;
import org.jmclbench.workload.BadInputException;
import org.jmclbench.workload.RunOptions;
import org.jmclbench.workload.data.Dataset;
import org.jmclbench.workload.engine.Engine;
import org.jmclbench.workload.engine.EngineInput;
import org.jmclbench.workload.engine.EngineResult;
import org.jmclbench.workload.output.HeapUse;

/**
 * {@code --engine javase}: the Java SE release engine ({@link RealTimeRun}), a dispatcher thread
 * and one handler thread per task; its one memory area is the heap.
 */
public final class JavaSeEngine implements Engine {

    @Override
    public String name() {
        return "javase";
    }

    @Override
    public String runtimeName(String jvmName) {
        return jvmName; // the thesis's engine keeps the JVM's own name
    }

    @Override
    public void checkOptions(RunOptions o) throws BadInputException {
        checkHeapOptions(name(), o);
    }

    /**
     * Refuses the options only the Java SE release loop ({@link RealTimeRun}) applies: another
     * engine would run without them and still record the spin and the load among its parameters.
     */
    public static void checkReleaseLoopOptions(String engine, RunOptions o) throws BadInputException {
        if (o.spinUs > 0) {
            throw BadInputException.ofOption("--spin-us", "the " + engine + " engine does not spin before a release"
                    + " (only javase does)");
        }
        if (o.gcLog) {
            throw BadInputException.ofOption("--gc-log", "the " + engine + " engine writes no GC log (only javase does)");
        }
        if (o.loadAllocMbPerS > 0) {
            throw BadInputException.ofOption("--load-alloc", "the " + engine + " engine starts no allocation load"
                    + " (only javase does)");
        }
    }

    /** The options of an engine whose one memory area is the heap: no scoped style, no SCJ areas. */
    public static void checkHeapOptions(String engine, RunOptions o) throws BadInputException {
        if (o.memory == MclConfig.Memory.SCOPED) {
            throw BadInputException.ofOption("--memory", "'scoped' is not a memory style of the " + engine + " engine"
                    + " (preallocated|allocating; scoped is --engine scj or hvm)");
        }
        if (!o.areaSizes.isEmpty()) {
            throw BadInputException.ofOption("--area-size", "sets SCJ memory areas: needs --engine scj or hvm");
        }
    }

    @Override
    public EngineResult run(EngineInput in) throws IOException {
        RunOptions options = in.options;
        Dataset d = in.dataset;
        Timeline timeline = d.timeline();
        JobRecords records = new JobRecords(timeline, options.covariance);
        Localizer localizer = in.newLocalizer();
        HeapUse heap = HeapUse.begin();
        JavaSeFacts facts = RealTimeRun.run(options, d, timeline, localizer, records, in.folder, in.err);
        return new EngineResult(records, Collections.singletonList(heap.end(facts.allocatedBytes(), records)), facts);
    }
}
