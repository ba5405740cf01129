package org.jmclbench.verification.seeded.mission;

import org.jmclbench.core.mcl.AbortSignal;
import org.jmclbench.core.mcl.Localizer;
import org.jmclbench.core.mcl.MclConfig;
import org.jmclbench.core.mcl.Playground;
import org.jmclbench.scj.OverrunPolicy;
import org.jmclbench.verification.mission.CheckedConfiguration;

/**
 * Seeded P3 bug in the real mission: the predict job commits its work (the real localizer's
 * predict, never aborted) and only then polls the abort request, reporting an abort after the
 * robot has changed.
 */
public final class CommitBeforePollConfiguration extends CheckedConfiguration {

    public CommitBeforePollConfiguration(MclConfig mcl, OverrunPolicy policy, double timeScale) {
        super(mcl, policy, timeScale);
    }

    @Override
    protected Localizer localizer(Playground playground, double startX, double startY, double startTheta) {
        return new Faulty(super.localizer(playground, startX, startY, startTheta));
    }

    static final class Faulty extends Delegating {
        Faulty(Localizer inner) {
            super(inner);
        }

        @Override
        public boolean update(double angle, AbortSignal abort) {
            inner.update(angle, AbortSignal.NEVER);
            return !abort.abortRequested();
        }

        @Override
        public boolean predict(double dx, double dy, double dtheta, AbortSignal abort) {
            inner.predict(dx, dy, dtheta, AbortSignal.NEVER);
            return !abort.abortRequested();
        }
    }
}
