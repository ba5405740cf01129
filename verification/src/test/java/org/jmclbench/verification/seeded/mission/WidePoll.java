package org.jmclbench.verification.seeded.mission;

import org.jmclbench.core.mcl.AbortSignal;
import org.jmclbench.core.mcl.Localizer;
import org.jmclbench.core.mcl.DelegatingLocalizer;

/**
 * Seeded P4 bug: the predict job polls every fourth poll interval (as a loop whose poll mask is
 * {@code (pollMask << 2) | 3} does): only every fourth of the shipped job's polls reaches the
 * abort request.
 */
public final class WidePoll extends DelegatingLocalizer implements AbortSignal {
    private AbortSignal job;
    private int polls;

    public WidePoll(Localizer shipped) {
        super(shipped);
    }

    @Override
    public boolean predict(double dx, double dy, double dtheta, AbortSignal abort) {
        job = abort;
        polls = 0;
        return inner.predict(dx, dy, dtheta, this);
    }

    @Override
    public boolean abortRequested() {
        return polls++ % 4 == 0 && job.abortRequested();
    }
}
