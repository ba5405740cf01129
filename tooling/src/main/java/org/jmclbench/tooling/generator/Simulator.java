package org.jmclbench.tooling.generator;

import java.util.ArrayList;
import java.util.List;

import org.jmclbench.core.mcl.Angles;
import org.jmclbench.core.mcl.Rng;

/**
 * The robot simulator: a differential-drive robot follows the scenario's route in steps of
 * 5 ms (constant v and w in a step, so the true path is a chain of arcs); every 50 ms the
 * odometry reports the increment since the previous reading in that reading's frame, with
 * noise; the laser turret turns at 3 rev/s and reports each beacon at the exact time its beam
 * crosses the beacon's bearing, solved by bisection on the continuous path.
 *
 * <p>All randomness comes from one {@link Rng} seeded with the seed, drawn in time order, and
 * all trigonometry is {@link StrictMath}, so the same inputs give the same bits on every JVM.
 * Draw order: the turret's starting angle, then, step by step, for each beam crossing (in
 * time order) one uniform (missed?) and one Gaussian (angle noise), and at each odometry time
 * three Gaussians (dx, dy, dtheta noise).
 */
public final class Simulator {
    /** Odometry readings per second (a reading every 50 ms). */
    public static final int ODOMETRY_RATE = 20;
    /** Simulation steps per odometry period (a step is 5 ms). */
    public static final int STEPS_PER_ODOMETRY = 10;
    /** Laser turret speed, revolutions per second. */
    public static final double LASER_RPS = 3.0;
    /** Crossing times are solved to this precision, seconds. */
    public static final double CROSSING_TOLERANCE = 1e-9;

    private static final double TURRET_RATE = LASER_RPS * Angles.TWO_PI;

    private final Playground playground;
    private final SensorNoise noise;

    public Simulator(Playground playground, SensorNoise noise) {
        this.playground = playground;
        this.noise = noise;
    }

    /** Simulates {@code odometryCount} odometry periods (duration = count / 20 s) of the scenario. */
    public SimulatedRun run(Scenario scenario, long seed, int odometryCount) {
        Rng rng = new Rng(seed);
        double phase = Angles.TWO_PI * rng.uniform();
        int rate = ODOMETRY_RATE * STEPS_PER_ODOMETRY;
        int steps = odometryCount * STEPS_PER_ODOMETRY;
        int kidnapStep = scenario.kidnap() == null ? -1
                : (int) Math.round(scenario.kidnap().time() * rate);

        RouteFollower follower = new RouteFollower(scenario.route(), scenario.loop());
        Trajectory trajectory = new Trajectory();
        double[][] odometry = new double[odometryCount][];
        double[][] real = new double[odometryCount][];
        List<double[]> laser = new ArrayList<>();
        List<double[]> crossings = new ArrayList<>();

        Pose pose = scenario.start();
        Pose lastReading = pose;
        for (int j = 0; j < steps; j++) {
            double ta = (double) j / rate;
            double tb = (double) (j + 1) / rate;
            if (j == kidnapStep) {
                // Carried away: the wheels do not turn, so the odometry sees nothing of the jump.
                pose = scenario.kidnap().pose();
                lastReading = pose;
                follower.stop();
            }
            follower.step(ta, pose, tb - ta);
            trajectory.add(ta, tb, pose.x(), pose.y(), pose.theta(), follower.v(), follower.w());
            int piece = trajectory.size() - 1;

            crossings.clear();
            for (int b = 0; b < playground.beacons().size(); b++) {
                double[] beacon = playground.beacons().get(b);
                double ea = beamOffset(trajectory, piece, ta, beacon, phase);
                double eb = beamOffset(trajectory, piece, tb, beacon, phase);
                // The offset grows by less than 0.2 rad in a step (the turret outruns any
                // bearing change), so a sign change near zero is one crossing, never the wrap at pi.
                if (ea < 0 && eb >= 0 && ea > -1 && eb < 1) {
                    crossings.add(new double[] {solveCrossing(trajectory, piece, ta, tb, beacon, phase), b});
                }
            }
            crossings.sort((p, q) -> Double.compare(p[0], q[0]));
            for (double[] c : crossings) {
                boolean missed = rng.uniform() < noise.missProbability();
                double angleNoise = noise.laserSigma() * rng.gaussian();
                if (!missed) {
                    double[] beacon = playground.beacons().get((int) c[1]);
                    laser.add(new double[] {c[0], Angles.wrap2pi(bearing(trajectory.poseIn(piece, c[0]), beacon) + angleNoise)});
                }
            }

            pose = trajectory.poseIn(piece, tb);
            if ((j + 1) % STEPS_PER_ODOMETRY == 0) {
                int k = (j + 1) / STEPS_PER_ODOMETRY;
                double t = (double) k / ODOMETRY_RATE;
                odometry[k - 1] = odometryReading(t, lastReading, pose, rng);
                real[k - 1] = new double[] {t, pose.x(), pose.y(), Angles.wrap2pi(pose.theta())};
                lastReading = pose;
            }
        }
        return new SimulatedRun(scenario, seed, odometryCount, noise, playground, phase, odometry,
                laser.toArray(new double[0][]), real, trajectory);
    }

    /** The wheels' report of the motion from {@code from} to {@code to}, in {@code from}'s frame, with noise. */
    private double[] odometryReading(double t, Pose from, Pose to, Rng rng) {
        double ddx = to.x() - from.x();
        double ddy = to.y() - from.y();
        double c = StrictMath.cos(from.theta());
        double s = StrictMath.sin(from.theta());
        double dx = c * ddx + s * ddy;
        double dy = -s * ddx + c * ddy;
        double dtheta = to.theta() - from.theta();
        double d = Math.sqrt(dx * dx + dy * dy);
        double sigmaXY = noise.alphaXY() * d + noise.floorXY();
        double sigmaTheta = noise.alphaTheta() * Math.abs(dtheta) + noise.alphaThetaXY() * d + noise.floorTheta();
        double nx = dx + sigmaXY * rng.gaussian();
        double ny = dy + sigmaXY * rng.gaussian();
        double nt = dtheta + sigmaTheta * rng.gaussian();
        return new double[] {t, nx, ny, nt};
    }

    /** The turret's angle relative to the heading at time t, in [0, 2pi). */
    static double turretAngle(double phase, double t) {
        return Angles.wrap2pi(phase + TURRET_RATE * t);
    }

    /** The beacon's bearing relative to the heading of the pose, in [0, 2pi) (StrictMath, so portable). */
    static double bearing(Pose pose, double[] beacon) {
        return Angles.wrap2pi(StrictMath.atan2(beacon[1] - pose.y(), beacon[0] - pose.x()) - pose.theta());
    }

    /** Turret angle minus the beacon's bearing at time t, in [-pi, pi): zero when the beam is on the beacon. */
    private static double beamOffset(Trajectory trajectory, int piece, double t, double[] beacon, double phase) {
        return Angles.wrapPi(phase + TURRET_RATE * t - bearing(trajectory.poseIn(piece, t), beacon));
    }

    /** Bisection for the time in (ta, tb] at which the beam offset crosses zero upwards. */
    private static double solveCrossing(Trajectory trajectory, int piece, double ta, double tb, double[] beacon,
            double phase) {
        double lo = ta;
        double hi = tb;
        while (hi - lo > CROSSING_TOLERANCE) {
            double mid = 0.5 * (lo + hi);
            if (mid <= lo || mid >= hi) {
                break;
            }
            if (beamOffset(trajectory, piece, mid, beacon, phase) < 0) {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        return hi;
    }
}
