package org.jmclbench.core.mcl;

/**
 * The {@code preallocated} memory style (ALGORITHM 9): flat arrays allocated once, two
 * particle buffers and a working copy of the generator, so that a job writes only into the
 * spare buffer and commits by swapping references. No allocation once constructed.
 */
public final class PreallocatedLocalizer extends CommittedParticles {
    // The spare buffer a job writes into, swapped with the committed particles at its commit.
    private double[] spareX;
    private double[] spareY;
    private double[] spareTheta;

    private final double[] weight;
    private final int[] index;
    private final double[] cumulative;

    // The committed generator and the copy a job draws from until it commits.
    private Rng rng;
    private Rng work;

    // An update's results before its commit.
    private final double[] newEst = new double[3];
    private final double[] newCov = new double[6];

    public PreallocatedLocalizer(MclConfig config, Playground playground, double startX, double startY, double startTheta) {
        super(config, playground);
        spareX = new double[n];
        spareY = new double[n];
        spareTheta = new double[n];
        weight = new double[n];
        index = new int[n];
        cumulative = config.resample == MclConfig.Resample.MULTINOMIAL ? new double[n] : null;
        rng = new Rng(config.seed);
        work = new Rng(config.seed);
        Initialisation.place(config, playground, startX, startY, startTheta, rng, x, y, theta, est);
    }

    @Override
    public boolean predict(double dx, double dy, double dtheta, AbortSignal abort) {
        Rng r = work;
        r.copyFrom(rng);
        if (!FilterSteps.predict(x, y, theta, spareX, spareY, spareTheta, n, dx, dy, dtheta, r, abort, pollMask)) {
            return false;
        }
        // Commit, then move the estimate without noise.
        commitParticles();
        FilterSteps.moveEstimate(est, dx, dy, dtheta);
        return true;
    }

    @Override
    public boolean update(double angle, AbortSignal abort) {
        double[] w = weight;
        if (!FilterSteps.weigh(x, y, theta, w, n, angle, playground, abort, pollMask)) {
            return false;
        }
        if (!FilterSteps.summarise(x, y, theta, w, n, config, newEst, newCov, abort, pollMask)) {
            return false;
        }
        Rng r = work;
        r.copyFrom(rng);
        if (!FilterSteps.resample(x, y, theta, w, n, config.resample, r, index, cumulative, spareX, spareY,
                spareTheta, abort, pollMask)) {
            return false;
        }
        commitParticles();
        commitEstimate(newEst, newCov);
        return true;
    }

    // A job's commit: its buffers and its generator become the committed ones, by swapping
    // references, so that the old ones are the next job's spares.
    private void commitParticles() {
        Rng r = rng;
        rng = work;
        work = r;
        double[] t = x;
        x = spareX;
        spareX = t;
        t = y;
        y = spareY;
        spareY = t;
        t = theta;
        theta = spareTheta;
        spareTheta = t;
    }
}
