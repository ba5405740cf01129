package org.jmclbench.verification;

import org.jmclbench.verification.mission.MissionDriver;
import org.jmclbench.verification.mission.MissionFault;

import java.util.ArrayList;
import java.util.List;

/**
 * One input of the {@link MissionDriver}: the policy, the memory style, the events (odometry
 * events 50 ms apart, laser event k 2 ms after odometry event k for k even, 2 ms before it for k
 * odd; a job takes 5 ms of virtual time), the particles, the
 * poll interval and whether the covariance is computed.
 */
public record MissionRun(String policy, String memory, int odometry, int laser, int particles, int poll,
                         boolean covariance, boolean coinciding) {

    /** The mission checks' input: two odometry and two laser events, one particle, poll every 64. */
    public static MissionRun of(String policy, String memory) {
        return new MissionRun(policy, memory, 2, 2, 1, 64, false, false);
    }

    /** This input on other events. */
    public MissionRun events(int odometryEvents, int laserEvents) {
        return new MissionRun(policy, memory, odometryEvents, laserEvents, particles, poll, covariance, coinciding);
    }

    /** This input with other particles and poll interval. */
    public MissionRun particles(int count, int pollInterval) {
        return new MissionRun(policy, memory, odometry, laser, count, pollInterval, covariance, coinciding);
    }

    /** This input with the covariance computed (the {@code -c} path). */
    public MissionRun withCovariance() {
        return new MissionRun(policy, memory, odometry, laser, particles, poll, true, coinciding);
    }

    /**
     * This input with laser event k at the instant of odometry event k: events at one time are
     * decided together, but their handlers still run at that instant, so a handler's admission can
     * meet a job starting (a lock-order inversion between the two is reachable only so).
     */
    public MissionRun atOdometryInstants() {
        return new MissionRun(policy, memory, odometry, laser, particles, poll, covariance, true);
    }

    /** The driver's arguments, with a seeded fault (a {@link MissionFault} or a faulty localizer) or none (null). */
    public List<String> args(Class<?> fault) {
        List<String> a = new ArrayList<>(List.of(policy, memory, Integer.toString(odometry), Integer.toString(laser),
                Integer.toString(particles), Integer.toString(poll), Boolean.toString(covariance),
                Boolean.toString(coinciding)));
        if (fault != null) {
            a.add(fault.getName());
        }
        return a;
    }

    /** What the input covers, for the table and the JSON. */
    public String scope() {
        return memory + ", " + odometry + " odometry + " + laser + " laser events" + (laser == 0 ? "" : coinciding ? " (coinciding)" : " (2 ms apart)")
                + ", " + particles + (particles == 1 ? " particle" : " particles") + ", poll every " + poll
                + (covariance ? ", covariance" : "");
    }
}
