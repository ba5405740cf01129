package org.jmclbench.verification.seeded.mission;

import org.jmclbench.core.mcl.AbortSignal;
import org.jmclbench.core.mcl.Localizer;
import org.jmclbench.core.mcl.MclConfig;
import org.jmclbench.core.mcl.Playground;
import org.jmclbench.core.policy.OverrunPolicy;
import org.jmclbench.verification.mission.CheckedConfiguration;
import org.jmclbench.verification.mission.DelegatingLocalizer;

/**
 * Seeded P3 bug in the real mission: commit before the abort poll. Each job applies its step to
 * the particles first and polls afterwards, so an aborted job leaves the robot changed.
 */
public final class CommitBeforePollConfiguration extends CheckedConfiguration {

    public CommitBeforePollConfiguration(MclConfig mcl, OverrunPolicy policy, double timeScale) {
        super(mcl, policy, timeScale);
    }

    @Override
    protected Localizer localizer(Playground playground, double startX, double startY, double startTheta) {
        return new Faulty(super.localizer(playground, startX, startY, startTheta));
    }

    /** Runs each job to completion, then asks whether it should have stopped. */
    static final class Faulty extends DelegatingLocalizer {
        Faulty(Localizer inner) {
            super(inner);
        }

        @Override
        public boolean predict(double dx, double dy, double dtheta, AbortSignal abort) {
            return inner.predict(dx, dy, dtheta, AbortSignal.NEVER) && !abort.abortRequested();
        }

        @Override
        public boolean update(double angle, AbortSignal abort) {
            return inner.update(angle, AbortSignal.NEVER) && !abort.abortRequested();
        }
    }
}
