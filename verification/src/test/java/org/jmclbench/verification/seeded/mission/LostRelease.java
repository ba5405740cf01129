package org.jmclbench.verification.seeded.mission;

import org.jmclbench.scj.JobGate;
import org.jmclbench.scj.MissionConfiguration;
import org.jmclbench.core.policy.OverrunPolicy;
import org.jmclbench.verification.mission.MissionFault;

/**
 * Seeded P5 bug: a lost release. The gate counts the first ended event as the last, so the
 * mission terminates before the later events are released; they never end.
 */
public final class LostRelease implements MissionFault {

    @Override
    public JobGate gate(MissionConfiguration configuration, int events) {
        return new EarlyEnd(configuration.policy, events);
    }

    /** Ends the mission at the first ended event. */
    public static final class EarlyEnd extends JobGate {
        EarlyEnd(OverrunPolicy policy, int events) {
            super(policy, events);
        }

        @Override
        public synchronized boolean ended() {
            super.ended();
            return true;
        }
    }
}
