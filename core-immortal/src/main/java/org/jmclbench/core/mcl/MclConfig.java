package org.jmclbench.core.mcl;

/** The filter's parameters for one run (docs/FORMATS.md section 2); immutable, built with {@link Builder}. */
public final class MclConfig {
    /** How the estimate is chosen from the weighted particles (ALGORITHM 7.3). */
    public enum Estimate { MEAN, BEST }

    /** How particles are resampled (ALGORITHM 7.5). */
    public enum Resample { SYSTEMATIC, MULTINOMIAL }

    /** How particles start (ALGORITHM 5). */
    public enum Init { KNOWN, UNIFORM }

    /**
     * Memory style (ALGORITHM 9): {@code preallocated} and {@code allocating} on the Java SE and
     * rtsj engines; {@code preallocated} and {@code scoped} (per-job temporaries in the release's
     * private memory, see {@link ScopedLocalizer}) on the SCJ mission (the scj and hvm engines).
     */
    public enum Memory { PREALLOCATED, ALLOCATING, SCOPED }

    /** Particle count N (at least 1). */
    public final int particles;
    public final Estimate estimate;
    public final Resample resample;
    public final Init init;
    public final Memory memory;
    /** Seed of the run's one random generator. */
    public final long seed;
    /** Whether each update computes the covariance (the thesis's -c). */
    public final boolean covariance;
    /**
     * Particles between two polls of the abort signal: a power of two, {@link MotionModel#ABORT_BLOCK}
     * (64) unless a verification run makes it small.
     */
    public final int pollInterval;

    private MclConfig(Builder b) {
        if (b.particles < 1) {
            throw new IllegalArgumentException("particles must be at least 1: " + b.particles);
        }
        particles = b.particles;
        estimate = b.estimate;
        resample = b.resample;
        init = b.init;
        memory = b.memory;
        seed = b.seed;
        covariance = b.covariance;
        if (b.pollInterval < 1 || (b.pollInterval & (b.pollInterval - 1)) != 0) {
            throw new IllegalArgumentException("poll interval must be a power of two: " + b.pollInterval);
        }
        pollInterval = b.pollInterval;
    }

    /** {@code pollInterval - 1}: a job polls when {@code (i & pollMask()) == 0}. */
    public int pollMask() {
        return pollInterval - 1;
    }

    /** A builder with the defaults of FORMATS section 2 (400 particles, mean, systematic, known, preallocated, seed 1). */
    public static Builder builder() {
        return new Builder();
    }

    /** The defaults with the given particle count. */
    public static MclConfig of(int particles) {
        return builder().particles(particles).build();
    }

    /** A builder starting from this configuration. */
    public Builder toBuilder() {
        return new Builder().particles(particles).estimate(estimate).resample(resample).init(init)
                .memory(memory).seed(seed).covariance(covariance).pollInterval(pollInterval);
    }

    @Override
    public String toString() {
        return "MclConfig[particles=" + particles + ", estimate=" + estimate + ", resample=" + resample
                + ", init=" + init + ", memory=" + memory + ", seed=" + seed + ", covariance=" + covariance
                + ", pollInterval=" + pollInterval + "]";
    }

    /** Collects the parameters of an {@link MclConfig}. */
    public static final class Builder {
        private int particles = 400;
        private Estimate estimate = Estimate.MEAN;
        private Resample resample = Resample.SYSTEMATIC;
        private Init init = Init.KNOWN;
        private Memory memory = Memory.PREALLOCATED;
        private long seed = 1;
        private boolean covariance;
        private int pollInterval = MotionModel.ABORT_BLOCK;

        public Builder particles(int v) {
            particles = v;
            return this;
        }

        public Builder estimate(Estimate v) {
            estimate = v;
            return this;
        }

        public Builder resample(Resample v) {
            resample = v;
            return this;
        }

        public Builder init(Init v) {
            init = v;
            return this;
        }

        public Builder memory(Memory v) {
            memory = v;
            return this;
        }

        public Builder seed(long v) {
            seed = v;
            return this;
        }

        public Builder covariance(boolean v) {
            covariance = v;
            return this;
        }

        public Builder pollInterval(int v) {
            pollInterval = v;
            return this;
        }

        public MclConfig build() {
            return new MclConfig(this);
        }
    }
}
