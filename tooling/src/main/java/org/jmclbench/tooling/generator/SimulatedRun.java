package org.jmclbench.tooling.generator;

/**
 * What one simulation produced: the three data series (rows {@code time dx dy dtheta},
 * {@code time angle}, {@code time x y theta}), the settings that produced them, and the true
 * continuous trajectory (for tests and checks).
 */
public record SimulatedRun(Scenario scenario, long seed, int odometryCount, SensorNoise noise, Playground playground,
        double turretPhase, double[][] odometry, double[][] laser, double[][] real, Trajectory trajectory) {

    /** Duration in seconds (the last odometry time). */
    public double duration() {
        return (double) odometryCount / Simulator.ODOMETRY_RATE;
    }

    /** The turret's angle relative to the heading at time t, in [0, 2pi). */
    public double turretAngle(double t) {
        return Simulator.turretAngle(turretPhase, t);
    }
}
