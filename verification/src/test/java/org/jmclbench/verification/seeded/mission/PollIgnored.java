package org.jmclbench.verification.seeded.mission;

import org.jmclbench.core.mcl.AbortSignal;
import org.jmclbench.core.mcl.Localizer;
import org.jmclbench.core.mcl.DelegatingLocalizer;

/**
 * Seeded P4 bug: an abort request seen and not honoured. The predict job polls once before it
 * starts and, when asked to stop, carries on with its whole step anyway (as a poll that leaves
 * only an inner loop would), stopping at the step's next poll at the earliest.
 */
public final class PollIgnored extends DelegatingLocalizer {

    public PollIgnored(Localizer shipped) {
        super(shipped);
    }

    @Override
    public boolean predict(double dx, double dy, double dtheta, AbortSignal abort) {
        abort.abortRequested();
        return inner.predict(dx, dy, dtheta, abort);
    }
}
