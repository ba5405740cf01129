package org.jmclbench.hvm.launcher;

import java.io.File;
import java.io.IOException;

import org.jmclbench.workload.BadInputException;
import org.jmclbench.workload.RunFailure;
import org.jmclbench.workload.RunOptions;
import org.jmclbench.workload.UnsupportedRunException;
import org.jmclbench.workload.data.Dataset;
import org.jmclbench.workload.engine.EngineInput;
import org.jmclbench.workload.engine.EngineResult;
import org.jmclbench.scj.MissionConfiguration;
import org.jmclbench.workload.scj.HvmOptionRules;
import org.jmclbench.workload.scj.ScjEngine;
import org.jmclbench.workload.scj.ScjRun;

/**
 * {@code --engine hvm}: the same SCJ mission as {@link ScjEngine}, with its options and checks,
 * compiled to a native executable by the icecap HVM ({@link HvmRun}, docs/HVM.md).
 */
public final class HvmEngine extends ScjEngine {
    /** The registration through java.util.ServiceLoader (META-INF/services) needs a public constructor. */
    public HvmEngine() {
    }

    @Override
    public String name() {
        return "hvm";
    }

    @Override
    public String runtimeName(String jvmName) {
        return "hvm"; // a VM of its own, not the JVM that drives it
    }

    /**
     * The options the HVM run has nothing to do with ({@link HvmOptionRules}: warm-up, spin, GC
     * log), then the scj engine's checks.
     */
    @Override
    public void checkOptions(RunOptions o) throws BadInputException {
        HvmOptionRules.check(o);
        super.checkOptions(o); // after the HVM's own reasons for the options the scj engine refuses too
    }

    /**
     * The scj engine's checks, then the HVM's limits ({@link HvmLimits}: its arrays, then its heap,
     * which must hold the areas' backing store): a run past them is unsupported; then HVM_SRC
     * ({@link HvmRun#checkSource}).
     */
    @Override
    public void validate(RunOptions options, Dataset dataset) throws BadInputException, UnsupportedRunException {
        super.validate(options, dataset);
        String beyond = HvmLimits.beyond(options.mclConfig(), dataset.odometryCount() + dataset.laserCount());
        if (beyond == null) {
            MissionConfiguration config = ScjRun.configuration(options, options.mclConfig(), options.timeScale, true);
            beyond = HvmLimits.beyondHeap(HvmRun.areaSizes(config, dataset),
                    HvmLimits.heapBytes(new File(System.getProperty("jmclbench.home", "."))), !options.areaSizes.isEmpty());
        }
        if (beyond != null) {
            throw new UnsupportedRunException(beyond);
        }
        HvmRun.checkSource();
    }

    @Override
    public EngineResult run(EngineInput in) throws RunFailure, IOException {
        return HvmRun.run(in.options, in.dataset, in.folder, in.err);
    }
}
