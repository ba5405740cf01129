package org.jmclbench.tooling.generator;

import java.util.List;

import org.jmclbench.core.mcl.Angles;

/**
 * The robot's route-following controller: from the true pose and the current wheel speeds
 * it chooses the forward speed v and the turn rate w for the next simulation step, within
 * the robot's speed and acceleration limits, so that the motion is smooth. The legs of the
 * route are worked through in order; a looping route starts again at its first leg.
 */
final class RouteFollower {
    /** Top forward speed, m/s. */
    static final double V_MAX = 0.5;
    /** Forward acceleration and deceleration limit, m/s^2. */
    static final double ACCEL = 0.8;
    /** Deceleration planned when approaching a goal (below ACCEL, so the limit is never hit), m/s^2. */
    private static final double BRAKE = 0.5;
    /** Top turn rate, rad/s. */
    static final double W_MAX = 2.0;
    /** Turn rate on the spot, rad/s. */
    private static final double W_TURN = 1.6;
    /** Angular acceleration limit, rad/s^2. */
    static final double ANGULAR_ACCEL = 4.0;
    /** Cruise speed between goal points, m/s. */
    private static final double CRUISE = 0.45;
    /** A goal point is reached within this distance, m. */
    private static final double GOAL_TOLERANCE = 0.02;
    /** Heading error above which the robot stops and turns on the spot, and below which it drives again. */
    private static final double TURN_ENTER = 0.6;
    private static final double TURN_EXIT = 0.08;
    /** Pure-pursuit lookahead, m. */
    private static final double LOOKAHEAD = 0.3;

    private final List<Leg> legs;
    private final boolean loop;
    private int legIndex;
    private boolean legStarted;
    private double legStartTime;
    private boolean turning;
    private int pathIndex;

    private double v;
    private double w;

    RouteFollower(List<Leg> legs, boolean loop) {
        if (legs.isEmpty()) {
            throw new IllegalArgumentException("a route needs at least one leg");
        }
        this.legs = legs;
        this.loop = loop;
    }

    /** Current forward speed, m/s. */
    double v() {
        return v;
    }

    /** Current turn rate, rad/s. */
    double w() {
        return w;
    }

    /** The robot was picked up: the wheels stand still. */
    void stop() {
        v = 0;
        w = 0;
    }

    /** Chooses v and w for the step [t, t + dt] from the pose at t. */
    void step(double t, Pose pose, double dt) {
        double vTarget = 0;
        double wTarget = 0;
        // A finished leg hands over to the next one within the same step; at most one pass
        // through the route, so a route of only finished legs ends standing still.
        for (int tries = 0; tries <= legs.size(); tries++) {
            if (legIndex >= legs.size()) {
                break;
            }
            Leg leg = legs.get(legIndex);
            if (!legStarted) {
                startLeg(leg, t, pose);
            }
            double[] target = control(leg, t, pose);
            if (target != null) {
                vTarget = target[0];
                wTarget = target[1];
                break;
            }
            legIndex++;
            legStarted = false;
            if (legIndex == legs.size() && loop) {
                legIndex = 0;
            }
        }
        v = limit(v + limit(vTarget - v, ACCEL * dt), V_MAX);
        w = limit(w + limit(wTarget - w, ANGULAR_ACCEL * dt), W_MAX);
    }

    private void startLeg(Leg leg, double t, Pose pose) {
        legStarted = true;
        legStartTime = t;
        turning = false;
        if (leg instanceof Leg.FollowPath path) {
            pathIndex = nearest(path, pose, 0, path.xs().length);
        }
    }

    /** The (v, w) targets for this leg, or null when the leg is finished. */
    private double[] control(Leg leg, double t, Pose pose) {
        if (leg instanceof Leg.DriveTo d) {
            double dx = d.x() - pose.x();
            double dy = d.y() - pose.y();
            double dist = Math.sqrt(dx * dx + dy * dy);
            if (dist < GOAL_TOLERANCE) {
                return null;
            }
            double err = Angles.wrapPi(StrictMath.atan2(dy, dx) - pose.theta());
            if (turning && Math.abs(err) < TURN_EXIT) {
                turning = false;
            } else if (!turning && Math.abs(err) > TURN_ENTER) {
                turning = true;
            }
            if (turning) {
                return new double[] {0, turnRate(err)};
            }
            double speed = Math.min(CRUISE, Math.sqrt(2 * BRAKE * Math.max(0, dist - GOAL_TOLERANCE / 2)));
            return new double[] {speed * Math.max(0, StrictMath.cos(err)), limit(3.0 * err, W_MAX)};
        }
        if (leg instanceof Leg.TurnTo turn) {
            double err = Angles.wrapPi(turn.theta() - pose.theta());
            if (Math.abs(err) < 0.01 && Math.abs(w) < 0.05) {
                return null;
            }
            return new double[] {0, turnRate(err)};
        }
        if (leg instanceof Leg.Wait wait) {
            return t - legStartTime >= wait.seconds() ? null : new double[] {0, 0};
        }
        Leg.FollowPath path = (Leg.FollowPath) leg;
        int n = path.xs().length;
        pathIndex = nearest(path, pose, pathIndex, 40);
        // The lookahead point: walk forward along the path until LOOKAHEAD away from the robot.
        int i = pathIndex;
        for (int k = 0; k < n; k++) {
            double ex = path.xs()[i] - pose.x();
            double ey = path.ys()[i] - pose.y();
            if (ex * ex + ey * ey >= LOOKAHEAD * LOOKAHEAD) {
                break;
            }
            i = (i + 1) % n;
        }
        double alpha = Angles.wrapPi(StrictMath.atan2(path.ys()[i] - pose.y(), path.xs()[i] - pose.x()) - pose.theta());
        double speed = path.cruise() * Math.max(0, StrictMath.cos(alpha));
        return new double[] {speed, limit(2 * path.cruise() * StrictMath.sin(alpha) / LOOKAHEAD, W_MAX)};
    }

    /** Turn rate towards a heading error, slowing down so as to stop on it. */
    private static double turnRate(double err) {
        double mag = Math.min(W_TURN, Math.min(3.0 * Math.abs(err), Math.sqrt(2 * ANGULAR_ACCEL * 0.6 * Math.abs(err))));
        return Math.copySign(mag, err);
    }

    /** The index of the path point nearest the pose among {@code count} points from {@code from} on. */
    private static int nearest(Leg.FollowPath path, Pose pose, int from, int count) {
        int n = path.xs().length;
        int best = from;
        double bestD = Double.POSITIVE_INFINITY;
        for (int k = 0; k < Math.min(count, n); k++) {
            int i = (from + k) % n;
            double ex = path.xs()[i] - pose.x();
            double ey = path.ys()[i] - pose.y();
            double d = ex * ex + ey * ey;
            if (d < bestD) {
                bestD = d;
                best = i;
            }
        }
        return best;
    }

    private static double limit(double value, double max) {
        return Math.max(-max, Math.min(max, value));
    }
}
