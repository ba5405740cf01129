package org.jmclbench.verification.seeded.mission;

import org.jmclbench.core.policy.OverrunPolicy;
import org.jmclbench.scj.JobGate;
import org.jmclbench.scj.MissionConfiguration;
import org.jmclbench.verification.mission.MissionFault;

/**
 * Seeded P7 bug: under skip the robot is never handed back after a job (the gate forgets to free
 * it), so every later event is dropped although the robot is idle. Every event still ends once.
 */
public final class RobotKept implements MissionFault {

    @Override
    public JobGate gate(MissionConfiguration configuration, int events) {
        return new KeepingGate(configuration.policy, events);
    }

    /** Never frees the robot. */
    public static final class KeepingGate extends JobGate {
        KeepingGate(OverrunPolicy policy, int events) {
            super(policy, events);
        }

        @Override
        public synchronized void release(int k) {
            // the robot stays with k
        }
    }
}
