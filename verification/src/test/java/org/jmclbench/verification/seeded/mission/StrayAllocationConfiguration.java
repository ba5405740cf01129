package org.jmclbench.verification.seeded.mission;

import org.jmclbench.core.mcl.AbortSignal;
import org.jmclbench.core.mcl.Localizer;
import org.jmclbench.core.mcl.MclConfig;
import org.jmclbench.core.mcl.Playground;
import org.jmclbench.core.policy.OverrunPolicy;
import org.jmclbench.verification.mission.CheckedConfiguration;
import org.jmclbench.verification.mission.DelegatingLocalizer;

/** Seeded P6 bug in the real mission: the predict job allocates a scratch array in its release. */
public final class StrayAllocationConfiguration extends CheckedConfiguration {

    public StrayAllocationConfiguration(MclConfig mcl, OverrunPolicy policy, double timeScale) {
        super(mcl, policy, timeScale);
    }

    @Override
    protected Localizer localizer(Playground playground, double startX, double startY, double startTheta) {
        return new Faulty(super.localizer(playground, startX, startY, startTheta));
    }

    /** Delegates, but allocates once per predict job. */
    static final class Faulty extends DelegatingLocalizer {
        Faulty(Localizer inner) {
            super(inner);
        }

        @Override
        public boolean predict(double dx, double dy, double dtheta, AbortSignal abort) {
            double[] scratch = new double[] {dx, dy, dtheta};
            return inner.predict(scratch[0], scratch[1], scratch[2], abort);
        }
    }
}
