package org.jmclbench.verification.mission;

import org.jmclbench.core.mcl.Localizer;
import org.jmclbench.scj.ImmortalEntry;
import org.jmclbench.scj.JobGate;
import org.jmclbench.scj.MissionConfiguration;

/**
 * A seeded bug, plugged into the real mission through its configuration seam by
 * {@link CheckedConfiguration}: each method may put a faulty part in place of the shipped one.
 * Implementations have a public no-argument constructor ({@link MissionDriver} makes them by
 * class name) and live in the test sources, never shipped with the mission.
 */
public interface MissionFault {
    /** The localizer the mission works on, given the shipped one (default: the shipped one). */
    default Localizer localizer(Localizer shipped) {
        return shipped;
    }

    /** A robot in place of the shipped one (it must keep the checks: extend {@link CheckedRobot}), or null. */
    default CheckedRobot robot(Localizer localizer, ImmortalEntry entry) {
        return null;
    }

    /** A gate in place of the shipped one, or null. */
    default JobGate gate(MissionConfiguration configuration, int events) {
        return null;
    }

    /** The shipped mission: no fault. */
    final class None implements MissionFault {
    }
}
