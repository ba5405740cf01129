package org.jmclbench.core.mcl;

/**
 * The steps of one predict or update job (ALGORITHM 6 and 7) on caller-provided arrays, shared
 * by both allocation-free memory styles so that the algorithm exists once: each step reads the
 * committed particles and writes only into the arrays it is given, polls the abort signal before
 * every block of particles ({@code pollMask + 1}, a power of two) and returns false when aborted.
 * No step allocates.
 */
final class FilterSteps {
    private FilterSteps() {
    }

    /** Moves every particle by the noisy increment into (qx, qy, qt), drawing from r; false when aborted. */
    static boolean predict(double[] px, double[] py, double[] pt, double[] qx, double[] qy, double[] qt, int n,
            double dx, double dy, double dtheta, Rng r, AbortSignal abort, int pollMask) {
        double d = Math.sqrt(dx * dx + dy * dy);
        double sigmaXY = MotionModel.sigmaXY(d);
        double sigmaTheta = MotionModel.sigmaTheta(d, dtheta);
        for (int i = 0; i < n; i++) {
            if ((i & pollMask) == 0 && abort.abortRequested()) {
                return false;
            }
            double ndx = dx + sigmaXY * r.gaussian();
            double ndy = dy + sigmaXY * r.gaussian();
            double ndt = dtheta + sigmaTheta * r.gaussian();
            double c = Math.cos(pt[i]);
            double s = Math.sin(pt[i]);
            qx[i] = px[i] + (ndx * c - ndy * s);
            qy[i] = py[i] + (ndx * s + ndy * c);
            qt[i] = Angles.wrap2pi(pt[i] + ndt);
        }
        return true;
    }

    /** The estimate moved by the increment without noise: est[0..2] = (x, y, theta) in place. */
    static void moveEstimate(double[] est, double dx, double dy, double dtheta) {
        double c = Math.cos(est[2]);
        double s = Math.sin(est[2]);
        est[0] += dx * c - dy * s;
        est[1] += dx * s + dy * c;
        est[2] = Angles.wrap2pi(est[2] + dtheta);
    }

    /** Normalised weights of every particle for the measured angle into w; false when aborted. */
    static boolean weigh(double[] px, double[] py, double[] pt, double[] w, int n, double angle, Playground p,
            AbortSignal abort, int pollMask) {
        // Every particle loop polls (verification's abort-poll rule): an abort request is
        // honoured within one block of particles wherever the job is.
        double total = 0.0;
        for (int i = 0; i < n; i++) {
            if ((i & pollMask) == 0 && abort.abortRequested()) {
                return false;
            }
            w[i] = Likelihood.of(px[i], py[i], pt[i], angle, p);
            total += w[i];
        }
        return Likelihood.normalise(w, n, total, abort, pollMask);
    }

    /**
     * The estimate of the weighted particles (ALGORITHM 7.3) into est[0..2] and, when the
     * configuration asks, their covariance into cov[0..5]; false when aborted.
     */
    static boolean summarise(double[] px, double[] py, double[] pt, double[] w, int n, MclConfig config,
            double[] est, double[] cov, AbortSignal abort, int pollMask) {
        return estimate(px, py, pt, w, n, config.estimate, est, abort, pollMask)
                && (!config.covariance || covariance(px, py, pt, w, n, est, cov, abort, pollMask));
    }

    /** The estimate of the weighted particles (ALGORITHM 7.3) into est[0..2]; false when aborted. */
    private static boolean estimate(double[] px, double[] py, double[] pt, double[] w, int n,
            MclConfig.Estimate mode, double[] est, AbortSignal abort, int pollMask) {
        if (mode == MclConfig.Estimate.MEAN) {
            double sx = 0.0;
            double sy = 0.0;
            double ss = 0.0;
            double sc = 0.0;
            for (int i = 0; i < n; i++) {
                if ((i & pollMask) == 0 && abort.abortRequested()) {
                    return false;
                }
                sx += w[i] * px[i];
                sy += w[i] * py[i];
                ss += w[i] * Math.sin(pt[i]);
                sc += w[i] * Math.cos(pt[i]);
            }
            est[0] = sx;
            est[1] = sy;
            est[2] = Angles.wrap2pi(Math.atan2(ss, sc));
        } else {
            int best = Likelihood.heaviest(w, n, abort, pollMask);
            if (best < 0) {
                return false;
            }
            est[0] = px[best];
            est[1] = py[best];
            est[2] = pt[best];
        }
        return true;
    }

    /** The weighted covariance around est (ALGORITHM 7.4) into cov[0..5]: cxx cxy cxt cyy cyt ctt; false when aborted. */
    private static boolean covariance(double[] px, double[] py, double[] pt, double[] w, int n, double[] est,
            double[] cov, AbortSignal abort, int pollMask) {
        double ex = est[0];
        double ey = est[1];
        double et = est[2];
        double cxx = 0.0;
        double cxy = 0.0;
        double cxt = 0.0;
        double cyy = 0.0;
        double cyt = 0.0;
        double ctt = 0.0;
        for (int i = 0; i < n; i++) {
            if ((i & pollMask) == 0 && abort.abortRequested()) {
                return false;
            }
            double ux = px[i] - ex;
            double uy = py[i] - ey;
            double ut = Angles.wrapPi(pt[i] - et);
            cxx += w[i] * ux * ux;
            cxy += w[i] * ux * uy;
            cxt += w[i] * ux * ut;
            cyy += w[i] * uy * uy;
            cyt += w[i] * uy * ut;
            ctt += w[i] * ut * ut;
        }
        cov[0] = cxx;
        cov[1] = cxy;
        cov[2] = cxt;
        cov[3] = cyy;
        cov[4] = cyt;
        cov[5] = ctt;
        return true;
    }

    /**
     * Resamples (ALGORITHM 7.5) with generator r into index and copies the chosen particles into
     * (qx, qy, qt); cumulative is the multinomial scratch (null for systematic). False when aborted.
     */
    static boolean resample(double[] px, double[] py, double[] pt, double[] w, int n, MclConfig.Resample mode,
            Rng r, int[] index, double[] cumulative, double[] qx, double[] qy, double[] qt, AbortSignal abort,
            int pollMask) {
        boolean completed;
        if (mode == MclConfig.Resample.SYSTEMATIC) {
            completed = Resampling.systematic(w, n, r.uniform() / n, index, abort, pollMask);
        } else {
            completed = Resampling.multinomial(w, n, r, index, cumulative, abort, pollMask);
        }
        if (!completed) {
            return false;
        }
        for (int m = 0; m < n; m++) {
            if ((m & pollMask) == 0 && abort.abortRequested()) {
                return false;
            }
            int k = index[m];
            qx[m] = px[k];
            qy[m] = py[k];
            qt[m] = pt[k];
        }
        return true;
    }
}
