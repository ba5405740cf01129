package org.jmclbench.verification.seeded.mission;

import org.jmclbench.core.mcl.AbortSignal;
import org.jmclbench.core.mcl.Localizer;
import org.jmclbench.core.mcl.DelegatingLocalizer;

/**
 * Seeded P6 bug (scoped style): the predict job keeps an array of its private memory in the
 * localizer, which lives in mission memory, instead of copying what it needs.
 */
public final class PrivateIntoMission extends DelegatingLocalizer {
    private double[] lastMotion;

    public PrivateIntoMission(Localizer shipped) {
        super(shipped);
    }

    @Override
    public boolean predict(double dx, double dy, double dtheta, AbortSignal abort) {
        lastMotion = new double[] {dx, dy, dtheta};
        return inner.predict(lastMotion[0], lastMotion[1], lastMotion[2], abort);
    }
}
