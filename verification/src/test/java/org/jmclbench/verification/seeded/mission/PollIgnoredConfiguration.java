package org.jmclbench.verification.seeded.mission;

import org.jmclbench.core.mcl.AbortSignal;
import org.jmclbench.core.mcl.Localizer;
import org.jmclbench.core.mcl.MclConfig;
import org.jmclbench.core.mcl.Playground;
import org.jmclbench.core.policy.OverrunPolicy;
import org.jmclbench.verification.mission.CheckedConfiguration;
import org.jmclbench.verification.mission.DelegatingLocalizer;

/**
 * Seeded P4 bug in the real mission: an abort request seen and not honoured. Each job polls
 * once before it starts and, when asked to stop, carries on with its whole step anyway (as a
 * poll that leaves only an inner loop would), stopping at the step's next poll at the earliest.
 */
public final class PollIgnoredConfiguration extends CheckedConfiguration {

    public PollIgnoredConfiguration(MclConfig mcl, OverrunPolicy policy, double timeScale) {
        super(mcl, policy, timeScale);
    }

    @Override
    protected Localizer localizer(Playground playground, double startX, double startY, double startTheta) {
        return new Faulty(super.localizer(playground, startX, startY, startTheta));
    }

    /** Polls first and ignores the answer. */
    static final class Faulty extends DelegatingLocalizer {
        Faulty(Localizer inner) {
            super(inner);
        }

        @Override
        public boolean predict(double dx, double dy, double dtheta, AbortSignal abort) {
            abort.abortRequested();
            return inner.predict(dx, dy, dtheta, abort);
        }

        @Override
        public boolean update(double angle, AbortSignal abort) {
            abort.abortRequested();
            return inner.update(angle, abort);
        }
    }
}
