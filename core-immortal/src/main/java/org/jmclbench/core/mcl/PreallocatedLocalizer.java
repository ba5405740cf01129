package org.jmclbench.core.mcl;

/**
 * The {@code preallocated} memory style (ALGORITHM 9): flat arrays allocated once, two
 * particle buffers and a working copy of the generator, so that a job writes only into the
 * spare buffer and commits by swapping references. No allocation once constructed.
 */
public final class PreallocatedLocalizer implements Localizer {
    private final int n;
    private final Playground playground;
    private final MclConfig config;

    // Committed particles and the spare buffer a job writes into.
    private double[] x;
    private double[] y;
    private double[] theta;
    private double[] spareX;
    private double[] spareY;
    private double[] spareTheta;

    private final double[] weight;
    private final int[] index;
    private final double[] cumulative;

    // The committed generator and the copy a job draws from until it commits.
    private Rng rng;
    private Rng work;

    private double estX;
    private double estY;
    private double estTheta;
    private final double[] cov = new double[6];

    public PreallocatedLocalizer(MclConfig config, Playground playground, double startX, double startY, double startTheta) {
        this.n = config.particles;
        this.config = config;
        this.playground = playground;
        x = new double[n];
        y = new double[n];
        theta = new double[n];
        spareX = new double[n];
        spareY = new double[n];
        spareTheta = new double[n];
        weight = new double[n];
        index = new int[n];
        cumulative = config.resample == MclConfig.Resample.MULTINOMIAL ? new double[n] : null;
        rng = new Rng(config.seed);
        work = new Rng(config.seed);
        if (config.init == MclConfig.Init.KNOWN) {
            for (int i = 0; i < n; i++) {
                x[i] = startX + MotionModel.INIT_SIGMA * rng.gaussian();
                y[i] = startY + MotionModel.INIT_SIGMA * rng.gaussian();
                theta[i] = Angles.wrap2pi(startTheta + MotionModel.INIT_SIGMA * rng.gaussian());
            }
            estX = startX;
            estY = startY;
            estTheta = Angles.wrap2pi(startTheta);
        } else {
            for (int i = 0; i < n; i++) {
                x[i] = playground.width * rng.uniform();
                y[i] = playground.height * rng.uniform();
                theta[i] = Angles.TWO_PI * rng.uniform();
            }
            estX = playground.width / 2;
            estY = playground.height / 2;
            estTheta = 0.0;
        }
    }

    @Override
    public boolean predict(double dx, double dy, double dtheta, AbortSignal abort) {
        Rng r = work;
        r.copyFrom(rng);
        double d = Math.sqrt(dx * dx + dy * dy);
        double sigmaXY = MotionModel.sigmaXY(d);
        double sigmaTheta = MotionModel.sigmaTheta(d, dtheta);
        double[] px = x;
        double[] py = y;
        double[] pt = theta;
        double[] qx = spareX;
        double[] qy = spareY;
        double[] qt = spareTheta;
        for (int i = 0; i < n; i++) {
            if ((i & (MotionModel.ABORT_BLOCK - 1)) == 0 && abort.abortRequested()) {
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
        // Commit: swap the buffers and the generator, then move the estimate without noise.
        swapBuffers();
        work = rng;
        rng = r;
        double c = Math.cos(estTheta);
        double s = Math.sin(estTheta);
        estX += dx * c - dy * s;
        estY += dx * s + dy * c;
        estTheta = Angles.wrap2pi(estTheta + dtheta);
        return true;
    }

    @Override
    public boolean update(double angle, AbortSignal abort) {
        double[] px = x;
        double[] py = y;
        double[] pt = theta;
        double[] w = weight;
        for (int i = 0; i < n; i++) {
            if ((i & (MotionModel.ABORT_BLOCK - 1)) == 0 && abort.abortRequested()) {
                return false;
            }
            w[i] = Likelihood.of(px[i], py[i], pt[i], angle, playground);
        }
        double total = 0.0;
        for (int i = 0; i < n; i++) {
            total += w[i];
        }
        if (total == 0.0 || Double.isNaN(total) || Double.isInfinite(total)) {
            double uniform = 1.0 / n;
            for (int i = 0; i < n; i++) {
                w[i] = uniform;
            }
        } else {
            for (int i = 0; i < n; i++) {
                w[i] = w[i] / total;
            }
        }

        double ex;
        double ey;
        double et;
        if (config.estimate == MclConfig.Estimate.MEAN) {
            double sx = 0.0;
            double sy = 0.0;
            double ss = 0.0;
            double sc = 0.0;
            for (int i = 0; i < n; i++) {
                sx += w[i] * px[i];
                sy += w[i] * py[i];
                ss += w[i] * Math.sin(pt[i]);
                sc += w[i] * Math.cos(pt[i]);
            }
            ex = sx;
            ey = sy;
            et = Angles.wrap2pi(Math.atan2(ss, sc));
        } else {
            int best = 0;
            for (int i = 1; i < n; i++) {
                if (w[i] > w[best]) {
                    best = i;
                }
            }
            ex = px[best];
            ey = py[best];
            et = pt[best];
        }

        double cxx = 0.0;
        double cxy = 0.0;
        double cxt = 0.0;
        double cyy = 0.0;
        double cyt = 0.0;
        double ctt = 0.0;
        if (config.covariance) {
            for (int i = 0; i < n; i++) {
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
        }

        Rng r = work;
        r.copyFrom(rng);
        boolean completed;
        if (config.resample == MclConfig.Resample.SYSTEMATIC) {
            completed = Resampling.systematic(w, n, r.uniform() / n, index, abort);
        } else {
            completed = Resampling.multinomial(w, n, r, index, cumulative, abort);
        }
        if (!completed) {
            return false;
        }
        double[] qx = spareX;
        double[] qy = spareY;
        double[] qt = spareTheta;
        for (int m = 0; m < n; m++) {
            if ((m & (MotionModel.ABORT_BLOCK - 1)) == 0 && abort.abortRequested()) {
                return false;
            }
            int k = index[m];
            qx[m] = px[k];
            qy[m] = py[k];
            qt[m] = pt[k];
        }
        // Commit.
        swapBuffers();
        work = rng;
        rng = r;
        estX = ex;
        estY = ey;
        estTheta = et;
        cov[0] = cxx;
        cov[1] = cxy;
        cov[2] = cxt;
        cov[3] = cyy;
        cov[4] = cyt;
        cov[5] = ctt;
        return true;
    }

    private void swapBuffers() {
        double[] t = x;
        x = spareX;
        spareX = t;
        t = y;
        y = spareY;
        spareY = t;
        t = theta;
        theta = spareTheta;
        spareTheta = t;
    }

    @Override
    public double estimateX() {
        return estX;
    }

    @Override
    public double estimateY() {
        return estY;
    }

    @Override
    public double estimateTheta() {
        return estTheta;
    }

    @Override
    public void covariance(double[] out) {
        System.arraycopy(cov, 0, out, 0, 6);
    }

    @Override
    public int particleCount() {
        return n;
    }

    @Override
    public void particle(int i, double[] out) {
        out[0] = x[i];
        out[1] = y[i];
        out[2] = theta[i];
    }
}
