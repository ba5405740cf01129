package org.jmclbench.verification.seeded.mission;

import org.jmclbench.core.mcl.AbortSignal;
import org.jmclbench.core.mcl.Localizer;
import org.jmclbench.core.mcl.DelegatingLocalizer;

/**
 * Seeded P3 bug: commit before the abort poll. The predict job applies its step to the particles
 * first and polls afterwards, so an aborted job leaves the robot changed.
 */
public final class CommitBeforePoll extends DelegatingLocalizer {

    public CommitBeforePoll(Localizer shipped) {
        super(shipped);
    }

    @Override
    public boolean predict(double dx, double dy, double dtheta, AbortSignal abort) {
        return inner.predict(dx, dy, dtheta, AbortSignal.NEVER) && !abort.abortRequested();
    }
}
