package org.jmclbench.workload.mcl;

import org.jmclbench.core.mcl.MotionModel;
import org.jmclbench.core.mcl.Playground;
import org.jmclbench.core.mcl.MclConfig;
import org.jmclbench.core.mcl.Localizer;
import org.jmclbench.core.mcl.AbortSignal;
import org.jmclbench.core.mcl.PreallocatedLocalizer;
import org.jmclbench.core.mcl.ScopedLocalizer;

/** Creates the localizer of the configured memory style, initialised per ALGORITHM 5. */
public final class Localizers {
    private Localizers() {
    }

    /**
     * A localizer for config on playground p; the start pose is used by the {@code known}
     * initialisation. The code of its jobs is loaded before it is returned (see {@link #prime}),
     * so that even a first job allocates nothing for class loading inside a measured window.
     */
    public static Localizer create(MclConfig config, Playground p, double startX, double startY, double startTheta) {
        prime(config, p, startX, startY, startTheta);
        return newLocalizer(config, p, startX, startY, startTheta);
    }

    /**
     * Runs a few jobs on a small throwaway localizer of the same configuration: loading the
     * classes of a job reads them from the jar and allocates (about 30 KB on HotSpot), which
     * must happen before the measured window, not in its first job. The real localizer's state
     * and generator are not touched.
     */
    static void prime(MclConfig config, Playground p, double startX, double startY, double startTheta) {
        MclConfig small = config.toBuilder().particles(Math.min(config.particles, 2 * MotionModel.ABORT_BLOCK)).build();
        Localizer l = newLocalizer(small, p, startX, startY, startTheta);
        double[] cov = new double[6];
        for (int i = 0; i < 2; i++) {
            l.predict(0.01, 0.0, 0.01, AbortSignal.NEVER);
            l.update(1.0, AbortSignal.NEVER);
            l.covariance(cov);
        }
    }

    private static Localizer newLocalizer(MclConfig config, Playground p, double startX, double startY,
            double startTheta) {
        switch (config.memory) {
            case ALLOCATING:
                return new AllocatingLocalizer(config, p, startX, startY, startTheta);
            case SCOPED:
                // On the heap here (tests, conformance); the SCJ engine builds it in mission memory.
                return new ScopedLocalizer(config, p, startX, startY, startTheta);
            case PREALLOCATED:
            default:
                return new PreallocatedLocalizer(config, p, startX, startY, startTheta);
        }
    }
}
