package org.jmclbench.verification.seeded.mission;

import org.jmclbench.core.mcl.AbortSignal;
import org.jmclbench.core.mcl.Localizer;
import org.jmclbench.scj.ImmortalEntry;
import org.jmclbench.scj.JobGate;
import org.jmclbench.scj.MissionConfiguration;
import org.jmclbench.core.policy.OverrunPolicy;
import org.jmclbench.scj.Robot;
import org.jmclbench.verification.mission.CheckedRobot;
import org.jmclbench.verification.mission.MissionFault;

/**
 * Seeded P1 bug: a lock-order inversion. The predict job, holding the robot, takes the gate's
 * lock; the laser sensor's admission, holding the gate, takes the robot's. A laser event
 * released while a predict job runs deadlocks the two.
 */
public final class LockInversion implements MissionFault {
    private InvertingRobot robot;

    @Override
    public CheckedRobot robot(Localizer localizer, ImmortalEntry entry) {
        robot = new InvertingRobot(localizer, entry);
        return robot;
    }

    @Override
    public JobGate gate(MissionConfiguration configuration, int events) {
        InvertingGate g = new InvertingGate(configuration.policy, events, robot);
        robot.gate = g;
        return g;
    }

    /** Takes the gate inside the robot's monitor. */
    public static final class InvertingRobot extends CheckedRobot {
        JobGate gate;

        InvertingRobot(Localizer localizer, ImmortalEntry entry) {
            super(localizer, entry);
        }

        @Override
        public synchronized boolean predict(int k, AbortSignal abort) {
            synchronized (gate) {
                return super.predict(k, abort);
            }
        }
    }

    /** Takes the robot inside the gate's monitor. */
    public static final class InvertingGate extends JobGate {
        private final Robot robot;

        InvertingGate(OverrunPolicy policy, int events, Robot robot) {
            super(policy, events);
            this.robot = robot;
        }

        @Override
        public synchronized boolean admit(int k) {
            synchronized (robot) {
                return super.admit(k);
            }
        }
    }
}
