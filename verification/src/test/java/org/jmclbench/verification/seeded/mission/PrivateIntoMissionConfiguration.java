package org.jmclbench.verification.seeded.mission;

import org.jmclbench.core.mcl.AbortSignal;
import org.jmclbench.core.mcl.Localizer;
import org.jmclbench.core.mcl.MclConfig;
import org.jmclbench.core.mcl.Playground;
import org.jmclbench.core.policy.OverrunPolicy;
import org.jmclbench.verification.mission.CheckedConfiguration;
import org.jmclbench.verification.mission.DelegatingLocalizer;

/**
 * Seeded P6 bug in the real mission: the predict job keeps its motion in an array allocated in
 * the release's private memory, referred to by the localizer, which lives in mission memory.
 */
public final class PrivateIntoMissionConfiguration extends CheckedConfiguration {

    public PrivateIntoMissionConfiguration(MclConfig mcl, OverrunPolicy policy, double timeScale) {
        super(mcl, policy, timeScale);
    }

    @Override
    protected Localizer localizer(Playground playground, double startX, double startY, double startTheta) {
        return new Faulty(super.localizer(playground, startX, startY, startTheta));
    }

    /** Delegates, but remembers the last motion in a private-memory array. */
    static final class Faulty extends DelegatingLocalizer {
        private double[] lastMotion;

        Faulty(Localizer inner) {
            super(inner);
        }

        @Override
        public boolean predict(double dx, double dy, double dtheta, AbortSignal abort) {
            lastMotion = new double[] {dx, dy, dtheta};
            return inner.predict(lastMotion[0], lastMotion[1], lastMotion[2], abort);
        }
    }
}
