package org.jmclbench.verification.seeded.mission;

import org.jmclbench.core.mcl.AbortSignal;
import org.jmclbench.core.mcl.Localizer;
import org.jmclbench.core.mcl.DelegatingLocalizer;

/** Seeded P6 bug (preallocated style): the predict job allocates a scratch array in its release. */
public final class StrayAllocation extends DelegatingLocalizer {

    public StrayAllocation(Localizer shipped) {
        super(shipped);
    }

    @Override
    public boolean predict(double dx, double dy, double dtheta, AbortSignal abort) {
        double[] scratch = new double[] {dx, dy, dtheta};
        return inner.predict(scratch[0], scratch[1], scratch[2], abort);
    }
}
