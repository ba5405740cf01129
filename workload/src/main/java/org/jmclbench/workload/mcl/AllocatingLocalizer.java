package org.jmclbench.workload.mcl;

import org.jmclbench.core.mcl.Angles;
import org.jmclbench.core.mcl.Likelihood;
import org.jmclbench.core.mcl.MotionModel;
import org.jmclbench.core.mcl.Resampling;
import org.jmclbench.core.mcl.Rng;
import org.jmclbench.core.mcl.Playground;
import org.jmclbench.core.mcl.MclConfig;
import org.jmclbench.core.mcl.Localizer;
import org.jmclbench.core.mcl.AbortSignal;
import org.jmclbench.core.mcl.PreallocatedLocalizer;

/**
 * The {@code allocating} memory style (ALGORITHM 9): a {@link Particle} object per particle
 * and new arrays and particles at every step, the garbage idiomatic Java produces. Same
 * arithmetic in the same order as {@link PreallocatedLocalizer}, hence the same estimates.
 */
final class AllocatingLocalizer implements Localizer {
    private final int n;
    private final Playground playground;
    private final MclConfig config;
    /** Poll the abort signal when {@code (i & pollMask) == 0}, as the preallocated style does. */
    private final int pollMask;

    private Particle[] particles;
    private Rng rng;
    private double estX;
    private double estY;
    private double estTheta;
    private double[] cov = new double[6];

    AllocatingLocalizer(MclConfig config, Playground playground, double startX, double startY, double startTheta) {
        this.n = config.particles;
        this.config = config;
        this.pollMask = config.pollMask();
        this.playground = playground;
        rng = new Rng(config.seed);
        particles = new Particle[n];
        if (config.init == MclConfig.Init.KNOWN) {
            for (int i = 0; i < n; i++) {
                double px = startX + MotionModel.INIT_SIGMA * rng.gaussian();
                double py = startY + MotionModel.INIT_SIGMA * rng.gaussian();
                double pt = Angles.wrap2pi(startTheta + MotionModel.INIT_SIGMA * rng.gaussian());
                particles[i] = new Particle(px, py, pt);
            }
            estX = startX;
            estY = startY;
            estTheta = Angles.wrap2pi(startTheta);
        } else {
            for (int i = 0; i < n; i++) {
                double px = playground.width * rng.uniform();
                double py = playground.height * rng.uniform();
                double pt = Angles.TWO_PI * rng.uniform();
                particles[i] = new Particle(px, py, pt);
            }
            estX = playground.width / 2;
            estY = playground.height / 2;
            estTheta = 0.0;
        }
    }

    @Override
    public boolean predict(double dx, double dy, double dtheta, AbortSignal abort) {
        Rng r = rng.copy();
        double d = Math.sqrt(dx * dx + dy * dy);
        double sigmaXY = MotionModel.sigmaXY(d);
        double sigmaTheta = MotionModel.sigmaTheta(d, dtheta);
        Particle[] next = new Particle[n];
        for (int i = 0; i < n; i++) {
            if ((i & pollMask) == 0 && abort.abortRequested()) {
                return false;
            }
            Particle p = particles[i];
            double ndx = dx + sigmaXY * r.gaussian();
            double ndy = dy + sigmaXY * r.gaussian();
            double ndt = dtheta + sigmaTheta * r.gaussian();
            double c = Math.cos(p.theta);
            double s = Math.sin(p.theta);
            next[i] = new Particle(p.x + (ndx * c - ndy * s), p.y + (ndx * s + ndy * c),
                    Angles.wrap2pi(p.theta + ndt));
        }
        particles = next;
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
        Particle[] ps = particles;
        double[] w = new double[n];
        for (int i = 0; i < n; i++) {
            if ((i & pollMask) == 0 && abort.abortRequested()) {
                return false;
            }
            w[i] = Likelihood.of(ps[i].x, ps[i].y, ps[i].theta, angle, playground);
        }
        double total = 0.0;
        for (int i = 0; i < n; i++) {
            if ((i & pollMask) == 0 && abort.abortRequested()) {
                return false;
            }
            total += w[i];
        }
        if (!Likelihood.normalise(w, n, total, abort, pollMask)) {
            return false;
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
                if ((i & pollMask) == 0 && abort.abortRequested()) {
                    return false;
                }
                Particle p = ps[i];
                sx += w[i] * p.x;
                sy += w[i] * p.y;
                ss += w[i] * Math.sin(p.theta);
                sc += w[i] * Math.cos(p.theta);
            }
            ex = sx;
            ey = sy;
            et = Angles.wrap2pi(Math.atan2(ss, sc));
        } else {
            int best = Likelihood.heaviest(w, n, abort, pollMask);
            if (best < 0) {
                return false;
            }
            ex = ps[best].x;
            ey = ps[best].y;
            et = ps[best].theta;
        }

        double[] c = new double[6];
        if (config.covariance) {
            for (int i = 0; i < n; i++) {
                if ((i & pollMask) == 0 && abort.abortRequested()) {
                    return false;
                }
                Particle p = ps[i];
                double ux = p.x - ex;
                double uy = p.y - ey;
                double ut = Angles.wrapPi(p.theta - et);
                c[0] += w[i] * ux * ux;
                c[1] += w[i] * ux * uy;
                c[2] += w[i] * ux * ut;
                c[3] += w[i] * uy * uy;
                c[4] += w[i] * uy * ut;
                c[5] += w[i] * ut * ut;
            }
        }

        Rng r = rng.copy();
        int[] index = new int[n];
        boolean completed;
        if (config.resample == MclConfig.Resample.SYSTEMATIC) {
            completed = Resampling.systematic(w, n, r.uniform() / n, index, abort, pollMask);
        } else {
            completed = Resampling.multinomial(w, n, r, index, new double[n], abort, pollMask);
        }
        if (!completed) {
            return false;
        }
        Particle[] next = new Particle[n];
        for (int m = 0; m < n; m++) {
            if ((m & pollMask) == 0 && abort.abortRequested()) {
                return false;
            }
            Particle p = ps[index[m]];
            next[m] = new Particle(p.x, p.y, p.theta);
        }
        particles = next;
        rng = r;
        estX = ex;
        estY = ey;
        estTheta = et;
        cov = c;
        return true;
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
        Particle p = particles[i];
        out[0] = p.x;
        out[1] = p.y;
        out[2] = p.theta;
    }
}
