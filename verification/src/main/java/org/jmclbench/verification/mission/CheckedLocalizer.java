package org.jmclbench.verification.mission;

import org.jmclbench.core.mcl.AbortSignal;
import org.jmclbench.core.mcl.Localizer;

/**
 * P3 on the real localizer: wraps the mission's localizer and, whenever a job returns false
 * (aborted), checks that everything the robot shows (every particle, the estimate, the
 * covariance) is bit-identical to what it was before the job. Allocation-free after
 * construction, so it does not disturb the release-allocation check.
 */
public final class CheckedLocalizer implements Localizer {
    private final Localizer inner;
    private final double[] pose = new double[3];
    private final double[] cov = new double[6];

    public CheckedLocalizer(Localizer inner) {
        this.inner = inner;
    }

    @Override
    public boolean predict(double dx, double dy, double dtheta, AbortSignal abort) {
        long before = fingerprint();
        boolean done = inner.predict(dx, dy, dtheta, abort);
        if (!done) {
            MissionDriver.check(fingerprint() == before, "P3 an aborted job changed the robot");
        }
        return done;
    }

    @Override
    public boolean update(double angle, AbortSignal abort) {
        long before = fingerprint();
        boolean done = inner.update(angle, abort);
        if (!done) {
            MissionDriver.check(fingerprint() == before, "P3 an aborted job changed the robot");
        }
        return done;
    }

    /** A hash of every bit of the robot's visible state. */
    private long fingerprint() {
        long h = Double.doubleToRawLongBits(inner.estimateX());
        h = h * 31 + Double.doubleToRawLongBits(inner.estimateY());
        h = h * 31 + Double.doubleToRawLongBits(inner.estimateTheta());
        inner.covariance(cov);
        for (int i = 0; i < 6; i++) {
            h = h * 31 + Double.doubleToRawLongBits(cov[i]);
        }
        for (int i = 0; i < inner.particleCount(); i++) {
            inner.particle(i, pose);
            h = h * 31 + Double.doubleToRawLongBits(pose[0]);
            h = h * 31 + Double.doubleToRawLongBits(pose[1]);
            h = h * 31 + Double.doubleToRawLongBits(pose[2]);
        }
        return h;
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
