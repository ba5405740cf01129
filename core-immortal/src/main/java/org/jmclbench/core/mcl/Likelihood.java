package org.jmclbench.core.mcl;

/** The laser's measurement model (ALGORITHM 7.1): a sum over beacons, since the beacon seen is not reported. */
public final class Likelihood {
    /** Standard deviation of the bearing error (rad). */
    public static final double SIGMA_LASER = 0.05;
    /** 2 * SIGMA_LASER^2, evaluated left to right as in C. */
    private static final double TWO_SIGMA_SQ = 2.0 * SIGMA_LASER * SIGMA_LASER;

    private Likelihood() {
    }

    /** The unnormalised likelihood of measuring {@code angle} from pose (x, y, theta) on playground p. */
    public static double of(double x, double y, double theta, double angle, Playground p) {
        double[] bx = p.beaconX;
        double[] by = p.beaconY;
        double w = 0.0;
        for (int b = 0; b < bx.length; b++) {
            double d = Angles.wrapPi(Angles.bearing(x, y, theta, bx[b], by[b]) - angle);
            w += Math.exp(-(d * d) / TWO_SIGMA_SQ);
        }
        return w;
    }

    /**
     * Divides the weights w[0..n) by their total in place; when the total is 0, NaN or infinite
     * (no particle explains the measurement) every weight becomes 1/n instead. Polls the abort
     * signal before every block of particles ({@code pollMask + 1}); false when aborted.
     */
    public static boolean normalise(double[] w, int n, double total, AbortSignal abort, int pollMask) {
        if (total == 0.0 || Double.isNaN(total) || Double.isInfinite(total)) {
            double uniform = 1.0 / n;
            for (int i = 0; i < n; i++) {
                if ((i & pollMask) == 0 && abort.abortRequested()) {
                    return false;
                }
                w[i] = uniform;
            }
        } else {
            for (int i = 0; i < n; i++) {
                if ((i & pollMask) == 0 && abort.abortRequested()) {
                    return false;
                }
                w[i] = w[i] / total;
            }
        }
        return true;
    }

    /**
     * The index of the heaviest of the weights w[0..n), the first one on a tie (the {@code max}
     * estimate's particle); polls the abort signal before every block of particles
     * ({@code pollMask + 1}) but the first; -1 when aborted.
     */
    public static int heaviest(double[] w, int n, AbortSignal abort, int pollMask) {
        int best = 0;
        for (int i = 1; i < n; i++) {
            if ((i & pollMask) == 0 && abort.abortRequested()) {
                return -1;
            }
            if (w[i] > w[best]) {
                best = i;
            }
        }
        return best;
    }
}
