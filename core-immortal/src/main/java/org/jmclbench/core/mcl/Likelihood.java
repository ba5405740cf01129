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
}
