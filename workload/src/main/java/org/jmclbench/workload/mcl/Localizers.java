package org.jmclbench.workload.mcl;

/** Creates the localizer of the configured memory style, initialised per ALGORITHM 5. */
public final class Localizers {
    private Localizers() {
    }

    /** A localizer for config on playground p; the start pose is used by the {@code known} initialisation. */
    public static Localizer create(MclConfig config, Playground p, double startX, double startY, double startTheta) {
        switch (config.memory) {
            case ALLOCATING:
                return new AllocatingLocalizer(config, p, startX, startY, startTheta);
            case PREALLOCATED:
            default:
                return new PreallocatedLocalizer(config, p, startX, startY, startTheta);
        }
    }
}
