package org.jmclbench.verification.seeded.mission;

import org.jmclbench.core.mcl.AbortSignal;
import org.jmclbench.core.mcl.Localizer;
import org.jmclbench.core.mcl.DelegatingLocalizer;

/**
 * Seeded P6 bug (scoped style): the update job caches a scratch array made in its private memory
 * in a thread-local, to reuse it at the next release. The store is the JDK's (not a field store
 * of the mission's code), so only the rule that the private memory is empty after the release
 * sees the array outliving it.
 */
public final class CachedScratch extends DelegatingLocalizer {
    private static final ThreadLocal<double[]> SCRATCH = new ThreadLocal<>();

    public CachedScratch(Localizer shipped) {
        super(shipped);
    }

    @Override
    public boolean update(double angle, AbortSignal abort) {
        double[] s = SCRATCH.get();
        if (s == null) {
            s = new double[1];
            SCRATCH.set(s);
        }
        s[0] = angle;
        return inner.update(s[0], abort);
    }
}
