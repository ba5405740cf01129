package org.jmclbench.tooling.runner;

import org.jmclbench.workload.RunOptions;
import org.jmclbench.workload.engine.Engine;
import org.jmclbench.workload.engine.EngineInput;
import org.jmclbench.workload.engine.EngineResult;

/**
 * An engine registered with the workload's registry only (through {@code META-INF/services}, as
 * the hvm launcher registers), so that the tests can check that the matrix and the comparison take
 * a new engine from that one registration. The matrix tests start fake JVMs, so it never runs.
 */
public final class RegisteredProbeEngine implements Engine {
    /** Its {@code --engine} value. */
    static final String NAME = "registered-probe";

    @Override
    public String name() {
        return NAME;
    }

    @Override
    public void checkOptions(RunOptions options) {
    }

    @Override
    public EngineResult run(EngineInput input) {
        throw new IllegalStateException("the " + NAME + " engine is registered for the tooling's tests, never run");
    }
}
