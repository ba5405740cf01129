package org.jmclbench.verification.seeded.mission;

import org.jmclbench.core.mcl.AbortSignal;
import org.jmclbench.core.mcl.Localizer;
import org.jmclbench.core.mcl.Rng;
import org.jmclbench.core.mcl.DelegatingLocalizer;

import java.lang.reflect.Field;

/**
 * Seeded P3 bug the robot's visible state does not show: an aborted predict job leaves the
 * committed generator advanced (as a job drawing from the generator itself instead of a copy
 * does). Particles, estimate and covariance are unchanged; the next completed job draws other
 * numbers, which the functional oracle's replay sees.
 */
public final class GeneratorAdvanced extends DelegatingLocalizer {
    // The shipped localizer's committed generator (the preallocated style swaps it at each commit).
    private final Field rng;

    public GeneratorAdvanced(Localizer shipped) throws ReflectiveOperationException {
        super(shipped);
        rng = shipped.getClass().getDeclaredField("rng");
        rng.setAccessible(true);
    }

    @Override
    public boolean predict(double dx, double dy, double dtheta, AbortSignal abort) {
        boolean done = inner.predict(dx, dy, dtheta, abort);
        if (!done) {
            try {
                ((Rng) rng.get(inner)).next();
            } catch (IllegalAccessException e) {
                throw new IllegalStateException(e);
            }
        }
        return done;
    }
}
