package org.jmclbench.verification.seeded.mission;

import org.jmclbench.core.mcl.MclConfig;
import org.jmclbench.core.policy.OverrunPolicy;
import org.jmclbench.scj.JobGate;
import org.jmclbench.verification.mission.CheckedConfiguration;

/**
 * Seeded P5 bug in the real mission: a lost release. The gate counts the first ended event as
 * the last, so the mission terminates before the later events are released; they never end.
 */
public final class LostReleaseConfiguration extends CheckedConfiguration {

    public LostReleaseConfiguration(MclConfig mcl, OverrunPolicy policy, double timeScale) {
        super(mcl, policy, timeScale);
    }

    @Override
    public JobGate newGate(int events) {
        return new JobGate(policy, events) {
            @Override
            public synchronized boolean ended() {
                super.ended();
                return true;
            }
        };
    }
}
