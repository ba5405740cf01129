package org.jmclbench.verification.seeded;

/** A preallocated release that allocates nothing (the allocation check must stay silent). */
public final class CleanRelease extends Release {
    private final double[] particles = new double[8];
    private final double[] spare = new double[8];

    @Override
    public void handleAsyncEvent() {
        for (int i = 0; i < particles.length; i++) {
            spare[i] = Math.sin(particles[i]) + StrictMath.sqrt(2.0);
        }
        System.arraycopy(spare, 0, particles, 0, particles.length);
    }
}
