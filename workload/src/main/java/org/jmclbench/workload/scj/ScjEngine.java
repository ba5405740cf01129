package org.jmclbench.workload.scj;

import java.io.IOException;

import org.jmclbench.core.mcl.MclConfig;
import org.jmclbench.workload.BadInputException;
import org.jmclbench.workload.RunFailure;
import org.jmclbench.workload.RunOptions;
import org.jmclbench.workload.UnsupportedRunException;
import org.jmclbench.workload.data.Dataset;
import org.jmclbench.workload.engine.Engine;
import org.jmclbench.workload.engine.EngineInput;
import org.jmclbench.workload.engine.EngineResult;
import org.jmclbench.workload.release.JavaSeEngine;

/** {@code --engine scj}: the SCJ mission (scj-mission) on this JVM through rtsj-compat ({@link ScjRun}). */
public class ScjEngine implements Engine {

    @Override
    public String name() {
        return "scj";
    }

    /** The mission's memory styles are preallocated and scoped; it has no allocating style, and no Java SE release loop. */
    @Override
    public void checkOptions(RunOptions o) throws BadInputException {
        if (o.memory == MclConfig.Memory.ALLOCATING) {
            throw BadInputException.ofOption("--memory", "'allocating' is not a memory style of the "
                    + name() + " engine (preallocated|scoped)");
        }
        JavaSeEngine.checkReleaseLoopOptions(name(), o);
    }

    /** A PeriodicEventHandler needs periodic odometry; the area sizes must fit the mission's areas. */
    @Override
    public void validate(RunOptions options, Dataset dataset) throws BadInputException, UnsupportedRunException {
        ScjRun.checkPeriodic(dataset);
        try {
            ScjRun.configuration(options, options.mclConfig(), options.timeScale, true);
        } catch (IllegalArgumentException e) {
            throw BadInputException.ofOption("--area-size", e.getMessage());
        }
    }

    @Override
    public EngineResult run(EngineInput in) throws RunFailure, IOException {
        return ScjRun.run(in.options, in.dataset);
    }
}
