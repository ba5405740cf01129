package org.jmclbench.tooling.generator;

import java.util.ArrayList;
import java.util.List;

/**
 * The robot's true, continuous motion: one piece per simulation step, with constant forward
 * speed v and turn rate w, i.e. an arc of a circle (a straight line when w = 0). The pose at
 * any time is exact (closed form), which is what the laser crossing times are solved on.
 */
public final class Trajectory {

    /**
     * One simulation step, from {@code start} to {@code end} (s): leaving (x, y, theta) at forward
     * speed {@code speed} (m/s) and turn rate {@code turnRate} (rad/s).
     */
    public record Piece(double start, double end, double x, double y, double theta, double speed, double turnRate) {
        /** The pose at time t within this piece (theta not wrapped). */
        public Pose poseAt(double t) {
            return arc(x, y, theta, speed, turnRate, t - start);
        }
    }

    private final List<Piece> pieces = new ArrayList<>();

    void add(double start, double end, double x, double y, double theta, double speed, double turnRate) {
        pieces.add(new Piece(start, end, x, y, theta, speed, turnRate));
    }

    /** Number of pieces (simulation steps). */
    public int size() {
        return pieces.size();
    }

    /** Piece i. */
    public Piece piece(int i) {
        return pieces.get(i);
    }

    /** The pose at time t within piece i (theta not wrapped). */
    public Pose poseIn(int i, double t) {
        return pieces.get(i).poseAt(t);
    }

    /**
     * The true pose at time t (theta not wrapped). At the instant of a kidnapping the pose
     * after the jump is returned.
     */
    public Pose poseAt(double t) {
        int lo = 0;
        int hi = pieces.size() - 1;
        while (lo < hi) { // the last piece starting at or before t
            int mid = (lo + hi + 1) >>> 1;
            if (pieces.get(mid).start() <= t) {
                lo = mid;
            } else {
                hi = mid - 1;
            }
        }
        return poseIn(lo, t);
    }

    /**
     * The pose after moving for tau seconds at speed v and turn rate w from (x, y, theta):
     * the chord of the arc, {@code 2 (v / w) sin(w tau / 2)}, along the mean heading, written
     * with sin(u)/u so that it stays exact as w goes to zero.
     */
    static Pose arc(double x, double y, double theta, double v, double w, double tau) {
        double half = 0.5 * w * tau;
        double sinc = Math.abs(half) < 1e-4 ? 1 - half * half / 6 : StrictMath.sin(half) / half;
        double chord = v * tau * sinc;
        double mid = theta + half;
        return new Pose(x + chord * StrictMath.cos(mid), y + chord * StrictMath.sin(mid), theta + w * tau);
    }
}
