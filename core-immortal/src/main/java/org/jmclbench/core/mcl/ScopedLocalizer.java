package org.jmclbench.core.mcl;

/**
 * The {@code scoped} memory style of the SCJ engine: the committed particle set, generator and
 * estimate are allocated once (in mission memory when constructed there), while each job allocates
 * its temporaries (the moved or resampled particles, weights, indices, the generator it draws from)
 * with {@code new}, so that under SCJ they land in the release's private memory and vanish when
 * the release ends. A completed job copies its result back into the committed arrays; an aborted
 * one leaves them untouched. The arithmetic is {@link PreallocatedLocalizer}'s, bit for bit.
 */
public final class ScopedLocalizer extends CommittedParticles {
    // The committed generator: with the committed particles, the only state that outlives a job.
    private final Rng rng;

    public ScopedLocalizer(MclConfig config, Playground playground, double startX, double startY, double startTheta) {
        super(config, playground);
        rng = new Rng(config.seed);
        Initialisation.place(config, playground, startX, startY, startTheta, rng, x, y, theta, est);
    }

    /**
     * Bytes one predict job allocates on a 64-bit JVM with compressed references: three particle
     * arrays (16-byte header + 8n each) and one generator (12-byte header + 4 longs, padded to 48).
     */
    public static long predictTemporaryBytes(int particles) {
        return 3 * doubleArrayBytes(particles) + RNG_BYTES;
    }

    /**
     * Bytes one update job allocates: weights, indices (16 + 4n, padded to 8), three particle
     * arrays, the multinomial scratch when used, the generator and the estimate/covariance pair.
     */
    public static long updateTemporaryBytes(int particles, MclConfig.Resample resample) {
        long intArray = (16 + 4L * particles + 7) / 8 * 8;
        long bytes = doubleArrayBytes(particles) + intArray + 3 * doubleArrayBytes(particles) + RNG_BYTES
                + doubleArrayBytes(3) + doubleArrayBytes(6);
        if (resample == MclConfig.Resample.MULTINOMIAL) {
            bytes += doubleArrayBytes(particles);
        }
        return bytes;
    }

    /** A double[] of n elements: 16-byte header + 8n. */
    static long doubleArrayBytes(int n) {
        return 16 + 8L * n;
    }

    /** An {@link Rng}: 12-byte header + 4 longs, padded to 8 bytes. */
    static final long RNG_BYTES = 48;

    @Override
    public boolean predict(double dx, double dy, double dtheta, AbortSignal abort) {
        double[] qx = new double[n];
        double[] qy = new double[n];
        double[] qt = new double[n];
        Rng r = rng.copy();
        if (!FilterSteps.predict(x, y, theta, qx, qy, qt, n, dx, dy, dtheta, r, abort, pollMask)) {
            return false;
        }
        commit(qx, qy, qt, r);
        FilterSteps.moveEstimate(est, dx, dy, dtheta);
        return true;
    }

    @Override
    public boolean update(double angle, AbortSignal abort) {
        double[] w = new double[n];
        if (!FilterSteps.weigh(x, y, theta, w, n, angle, playground, abort, pollMask)) {
            return false;
        }
        double[] newEst = new double[3];
        double[] newCov = new double[6];
        if (!FilterSteps.summarise(x, y, theta, w, n, config, newEst, newCov, abort, pollMask)) {
            return false;
        }
        Rng r = rng.copy();
        int[] index = new int[n];
        double[] cumulative = config.resample == MclConfig.Resample.MULTINOMIAL ? new double[n] : null;
        double[] qx = new double[n];
        double[] qy = new double[n];
        double[] qt = new double[n];
        if (!FilterSteps.resample(x, y, theta, w, n, config.resample, r, index, cumulative, qx, qy, qt, abort,
                pollMask)) {
            return false;
        }
        commit(qx, qy, qt, r);
        commitEstimate(newEst, newCov);
        return true;
    }

    /** Copies a completed job's particles and generator back into the committed (mission memory) state. */
    private void commit(double[] qx, double[] qy, double[] qt, Rng r) {
        System.arraycopy(qx, 0, x, 0, n);
        System.arraycopy(qy, 0, y, 0, n);
        System.arraycopy(qt, 0, theta, 0, n);
        rng.copyFrom(r);
    }
}
