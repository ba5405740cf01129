package org.jmclbench.core.mcl;

/**
 * What the two allocation-free memory styles share: the committed particle set and estimate
 * that outlive a job, and the read side of {@link Localizer} over them. A style decides where a
 * job's temporaries live and how a completed job commits (swap buffers, or copy back).
 */
abstract class CommittedParticles implements Localizer {
    final int n;
    final int pollMask;
    final Playground playground;
    final MclConfig config;
    // The committed particles (a style may swap these arrays for its spare ones when it commits).
    double[] x;
    double[] y;
    double[] theta;
    // The committed estimate (x, y, theta) and covariance.
    final double[] est = new double[3];
    final double[] cov = new double[6];

    CommittedParticles(MclConfig config, Playground playground) {
        this.n = config.particles;
        this.pollMask = config.pollMask();
        this.config = config;
        this.playground = playground;
        x = new double[n];
        y = new double[n];
        theta = new double[n];
    }

    /** Commits an update's estimate and covariance (zeros when the covariance is not computed). */
    final void commitEstimate(double[] newEst, double[] newCov) {
        est[0] = newEst[0];
        est[1] = newEst[1];
        est[2] = newEst[2];
        for (int i = 0; i < 6; i++) {
            cov[i] = config.covariance ? newCov[i] : 0.0;
        }
    }

    @Override
    public final double estimateX() {
        return est[0];
    }

    @Override
    public final double estimateY() {
        return est[1];
    }

    @Override
    public final double estimateTheta() {
        return est[2];
    }

    @Override
    public final void covariance(double[] out) {
        System.arraycopy(cov, 0, out, 0, 6);
    }

    @Override
    public final int particleCount() {
        return n;
    }

    @Override
    public final void particle(int i, double[] out) {
        out[0] = x[i];
        out[1] = y[i];
        out[2] = theta[i];
    }
}
