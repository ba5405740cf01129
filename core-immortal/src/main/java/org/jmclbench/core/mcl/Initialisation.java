package org.jmclbench.core.mcl;

/** The particles' start (ALGORITHM 5), shared by the allocation-free memory styles. */
final class Initialisation {
    private Initialisation() {
    }

    /** Places the n particles and sets the initial estimate est[0..2], drawing from rng. */
    static void place(MclConfig config, Playground playground, double startX, double startY, double startTheta,
            Rng rng, double[] x, double[] y, double[] theta, double[] est) {
        int n = config.particles;
        if (config.init == MclConfig.Init.KNOWN) {
            for (int i = 0; i < n; i++) {
                x[i] = startX + MotionModel.INIT_SIGMA * rng.gaussian();
                y[i] = startY + MotionModel.INIT_SIGMA * rng.gaussian();
                theta[i] = Angles.wrap2pi(startTheta + MotionModel.INIT_SIGMA * rng.gaussian());
            }
            est[0] = startX;
            est[1] = startY;
            est[2] = Angles.wrap2pi(startTheta);
        } else {
            for (int i = 0; i < n; i++) {
                x[i] = playground.width * rng.uniform();
                y[i] = playground.height * rng.uniform();
                theta[i] = Angles.TWO_PI * rng.uniform();
            }
            est[0] = playground.width / 2;
            est[1] = playground.height / 2;
            est[2] = 0.0;
        }
    }
}
