package org.jmclbench.core.mcl;

/**
 * A localizer that forwards everything to another: a subclass overrides only the jobs it changes
 * (verification's seeded bugs, tests that slow a job down). Allocates nothing of its own.
 */
public abstract class DelegatingLocalizer implements Localizer {
    protected final Localizer inner;

    protected DelegatingLocalizer(Localizer inner) {
        this.inner = inner;
    }

    @Override
    public boolean predict(double dx, double dy, double dtheta, AbortSignal abort) {
        return inner.predict(dx, dy, dtheta, abort);
    }

    @Override
    public boolean update(double angle, AbortSignal abort) {
        return inner.update(angle, abort);
    }

    @Override
    public double estimateX() {
        return inner.estimateX();
    }

    @Override
    public double estimateY() {
        return inner.estimateY();
    }

    @Override
    public double estimateTheta() {
        return inner.estimateTheta();
    }

    @Override
    public void covariance(double[] out) {
        inner.covariance(out);
    }

    @Override
    public int particleCount() {
        return inner.particleCount();
    }

    @Override
    public void particle(int i, double[] out) {
        inner.particle(i, out);
    }
}
