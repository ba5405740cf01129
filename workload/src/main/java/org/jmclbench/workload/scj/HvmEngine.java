package org.jmclbench.workload.scj;

import java.io.IOException;

import org.jmclbench.workload.RunFailure;
import org.jmclbench.workload.engine.EngineInput;
import org.jmclbench.workload.engine.EngineResult;

/**
 * {@code --engine hvm}: the same SCJ mission as {@link ScjEngine}, with its options and checks,
 * compiled to a native executable by the icecap HVM ({@link HvmRun}, docs/HVM.md).
 */
public final class HvmEngine extends ScjEngine {

    @Override
    public String name() {
        return "hvm";
    }

    @Override
    public String runtimeName(String jvmName) {
        return "hvm"; // a VM of its own, not the JVM that drives it
    }

    @Override
    public EngineResult run(EngineInput in) throws RunFailure, IOException {
        return HvmRun.run(in.options, in.dataset, in.folder, in.err);
    }
}
