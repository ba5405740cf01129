package org.jmclbench.core.record;

import org.jmclbench.core.timeline.Timeline;
import org.jmclbench.core.mcl.Angles;

/**
 * Localisation error per docs/ALGORITHM.md section 10: at each ground-truth time t_i, the
 * estimate committed by the latest completed job whose event time is at or before t_i (the
 * initial estimate when there is none), minus the true pose. Computed after the run.
 */
public final class Deviation {
    /** Ground-truth times (s), one row each. */
    public final double[] time;
    /** The estimate in force at each time. */
    public final double[] x;
    public final double[] y;
    public final double[] theta;
    /** Errors: ex, ey, the Euclidean exy and the wrapped angle et. */
    public final double[] dx;
    public final double[] dy;
    public final double[] dxy;
    public final double[] dtheta;

    private Deviation(int n) {
        time = new double[n];
        x = new double[n];
        y = new double[n];
        theta = new double[n];
        dx = new double[n];
        dy = new double[n];
        dxy = new double[n];
        dtheta = new double[n];
    }

    /**
     * The deviation series of a run's records against the ground truth (realTime, realX,
     * realY, realTheta: one row each, as the dataset's real-position file).
     */
    public static Deviation of(double[] realTime, double[] realX, double[] realY, double[] realTheta,
                               Timeline t, JobRecords r) {
        int n = realTime.length;
        Deviation v = new Deviation(n);
        double ex = r.initialX;
        double ey = r.initialY;
        double et = r.initialTheta;
        int k = 0;
        for (int i = 0; i < n; i++) {
            double ti = realTime[i];
            while (k < t.size() && t.time(k) <= ti) {
                if (r.completed(k)) {
                    ex = r.estX[k];
                    ey = r.estY[k];
                    et = r.estTheta[k];
                }
                k++;
            }
            v.time[i] = ti;
            v.x[i] = ex;
            v.y[i] = ey;
            v.theta[i] = et;
            double ddx = ex - realX[i];
            double ddy = ey - realY[i];
            v.dx[i] = ddx;
            v.dy[i] = ddy;
            v.dxy[i] = Math.sqrt(ddx * ddx + ddy * ddy);
            v.dtheta[i] = Angles.wrapPi(et - realTheta[i]);
        }
        return v;
    }

    /** Number of rows. */
    public int size() {
        return time.length;
    }

    /** Mean of |ex| (m). */
    public double meanAbsX() {
        return meanAbs(dx, 0, dx.length);
    }

    /** Mean of |ey| (m). */
    public double meanAbsY() {
        return meanAbs(dy, 0, dy.length);
    }

    /** Mean of exy (m). */
    public double meanXY() {
        return meanAbs(dxy, 0, dxy.length);
    }

    /** Mean of |et| (rad). */
    public double meanAbsTheta() {
        return meanAbs(dtheta, 0, dtheta.length);
    }

    /** Mean of |v[from..to-1]|; NaN for an empty range. */
    public static double meanAbs(double[] v, int from, int to) {
        if (to <= from) {
            return Double.NaN;
        }
        double s = 0;
        for (int i = from; i < to; i++) {
            s += Math.abs(v[i]);
        }
        return s / (to - from);
    }

    /** Max of |v|; NaN when empty. */
    public static double maxAbs(double[] v) {
        if (v.length == 0) {
            return Double.NaN;
        }
        double m = 0;
        for (double e : v) {
            m = Math.max(m, Math.abs(e));
        }
        return m;
    }
}
