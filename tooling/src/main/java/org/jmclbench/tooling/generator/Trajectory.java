package org.jmclbench.tooling.generator;

import java.util.Arrays;

/**
 * The robot's true, continuous motion: one piece per simulation step, with constant forward
 * speed v and turn rate w, i.e. an arc of a circle (a straight line when w = 0). The pose at
 * any time is exact (closed form), which is what the laser crossing times are solved on.
 */
public final class Trajectory {
    private double[] t0 = new double[1024];
    private double[] t1 = new double[1024];
    private double[] x0 = new double[1024];
    private double[] y0 = new double[1024];
    private double[] th0 = new double[1024];
    private double[] v = new double[1024];
    private double[] w = new double[1024];
    private int size;

    void add(double start, double end, double x, double y, double theta, double speed, double turnRate) {
        if (size == t0.length) {
            int n = size * 2;
            t0 = Arrays.copyOf(t0, n);
            t1 = Arrays.copyOf(t1, n);
            x0 = Arrays.copyOf(x0, n);
            y0 = Arrays.copyOf(y0, n);
            th0 = Arrays.copyOf(th0, n);
            v = Arrays.copyOf(v, n);
            w = Arrays.copyOf(w, n);
        }
        t0[size] = start;
        t1[size] = end;
        x0[size] = x;
        y0[size] = y;
        th0[size] = theta;
        v[size] = speed;
        w[size] = turnRate;
        size++;
    }

    /** Number of pieces (simulation steps). */
    public int size() {
        return size;
    }

    /** Start time of piece i. */
    public double start(int i) {
        return t0[i];
    }

    /** End time of piece i. */
    public double end(int i) {
        return t1[i];
    }

    /** Forward speed during piece i, m/s. */
    public double speed(int i) {
        return v[i];
    }

    /** Turn rate during piece i, rad/s. */
    public double turnRate(int i) {
        return w[i];
    }

    /** The pose at time t within piece i (theta not wrapped). */
    public Pose poseIn(int i, double t) {
        return arc(x0[i], y0[i], th0[i], v[i], w[i], t - t0[i]);
    }

    /**
     * The true pose at time t (theta not wrapped). At the instant of a kidnapping the pose
     * after the jump is returned.
     */
    public Pose poseAt(double t) {
        int lo = 0;
        int hi = size - 1;
        while (lo < hi) { // the last piece starting at or before t
            int mid = (lo + hi + 1) >>> 1;
            if (t0[mid] <= t) {
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
