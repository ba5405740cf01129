package org.jmclbench.verification.seeded.mission;

import org.jmclbench.scj.JobGate;
import org.jmclbench.scj.MissionConfiguration;
import org.jmclbench.core.policy.OverrunPolicy;
import org.jmclbench.verification.mission.MissionFault;

/**
 * Seeded P5 bug: a mission that never ends. The gate compares its count with one event too
 * many, so the last ended event does not request termination and the periodic handler goes on
 * being released; virtual time's horizon turns the hang into a counterexample.
 */
public final class NeverEnds implements MissionFault {

    @Override
    public JobGate gate(MissionConfiguration configuration, int events) {
        return new OffByOne(configuration.policy, events);
    }

    /** Counts to one more event than there are. */
    public static final class OffByOne extends JobGate {
        OffByOne(OverrunPolicy policy, int events) {
            super(policy, events + 1);
        }
    }
}
