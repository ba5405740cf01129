package org.jmclbench.core.mcl;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/** The laser likelihood (ALGORITHM 7.1): a sum over beacons, largest at the true pose. */
class LikelihoodTest {
    private static final Playground P = Playground.thesis();

    @Test
    void isTheSumOfAGaussianPerBeacon() {
        double x = 1.2;
        double y = 0.7;
        double th = 0.4;
        double a = 2.0;
        double expected = 0;
        for (int b = 0; b < 3; b++) {
            double d = Angles.wrapPi(Angles.bearing(x, y, th, P.beaconX[b], P.beaconY[b]) - a);
            expected += Math.exp(-d * d / (2 * Likelihood.SIGMA_LASER * Likelihood.SIGMA_LASER));
        }
        assertEquals(expected, Likelihood.of(x, y, th, a, P), 1e-15);
    }

    @Test
    void seeingABeaconExactlyGivesAtLeastOne() {
        for (int b = 0; b < 3; b++) {
            double a = Angles.bearing(1.0, 1.5, 2.0, P.beaconX[b], P.beaconY[b]);
            double w = Likelihood.of(1.0, 1.5, 2.0, a, P);
            assertTrue(w >= 1.0 && w <= 3.0, "likelihood " + w);
        }
        // An angle far from every beacon's bearing: nearly zero.
        double[] bearings = new double[3];
        for (int b = 0; b < 3; b++) {
            bearings[b] = Angles.bearing(1.0, 1.0, 0.0, P.beaconX[b], P.beaconY[b]);
        }
        assertTrue(Likelihood.of(1.0, 1.0, 0.0, Angles.wrap2pi(bearings[0] + 0.5), P) < 1e-10);
    }

    @Test
    void differenceIsWrappedAcrossZero() {
        // From (1, 1) heading 0 the beacon S1 (0, 1) is at pi; measured as just below 2pi it is far,
        // while S2's bearing near 2pi - 0.46 and a measurement across zero must count as near.
        double a = Angles.bearing(1.0, 1.0, 0.0, 3.0, 0.0); // S2, about 5.82 rad
        double wNear = Likelihood.of(1.0, 1.0, 0.0, Angles.wrap2pi(a + 0.01), P);
        assertEquals(Math.exp(-0.0001 / (2 * 0.0025)), wNear, 1e-3);
        // Heading chosen so that S2 is seen at 0.001 rad: a measurement of 2pi - 0.001 is 0.002 away.
        double th = Math.atan2(-1.0, 2.0) - 0.001;
        double w = Likelihood.of(1.0, 1.0, th, Angles.TWO_PI - 0.001, P);
        assertTrue(w > 0.99, "wrapped likelihood " + w);
    }

    @Test
    void threeMeasurementsAreMostLikelyAtTheTruePose() {
        double tx = 1.3;
        double ty = 0.8;
        double tt = 0.9;
        double[] a = new double[3];
        for (int b = 0; b < 3; b++) {
            a[b] = Angles.bearing(tx, ty, tt, P.beaconX[b], P.beaconY[b]);
        }
        double best = score(tx, ty, tt, a);
        for (double ex = -0.1; ex <= 0.1001; ex += 0.02) {
            for (double ey = -0.1; ey <= 0.1001; ey += 0.02) {
                for (double et = -0.1; et <= 0.1001; et += 0.02) {
                    if (Math.abs(ex) < 1e-9 && Math.abs(ey) < 1e-9 && Math.abs(et) < 1e-9) {
                        continue;
                    }
                    double s = score(tx + ex, ty + ey, tt + et, a);
                    assertTrue(s < best, "pose offset (" + ex + ", " + ey + ", " + et + ") scores " + s
                            + " >= " + best);
                }
            }
        }
    }

    /**
     * The weights become a distribution. Weights scaled by any other factor keep their ratios, and
     * the mission's tests compare its estimates with the ideal runs' of this same code, so a
     * wrong factor passed them all (the mutation score's weights-not-normalised).
     */
    @Test
    void normaliseDividesEveryWeightByTheTotal() {
        double[] w = {1.0, 2.0, 3.0, 4.0, 5.0};
        assertTrue(Likelihood.normalise(w, 4, 10.0, AbortSignal.NEVER, 1));
        double[] expected = {0.1, 0.2, 0.3, 0.4, 5.0}; // the fifth is past n: untouched
        for (int i = 0; i < w.length; i++) {
            assertEquals(expected[i], w[i], 1e-15, "weight " + i);
        }
    }

    @Test
    void heaviestIsTheFirstLargestWeight() {
        double[] w = {0.1, 0.3, 0.2, 0.3, 0.1};
        assertEquals(1, Likelihood.heaviest(w, 5, AbortSignal.NEVER, 0));
        assertEquals(0, Likelihood.heaviest(w, 1, AbortSignal.NEVER, 0));
    }

    @Test
    void heaviestPollsEveryBlockAfterTheFirstAndStopsOnAbort() {
        double[] w = new double[8];
        w[7] = 1.0;
        // pollMask 1: a poll before particles 2, 4 and 6 (particle 0 is the starting candidate, not visited)
        AbortAt never = new AbortAt(Integer.MAX_VALUE);
        assertEquals(7, Likelihood.heaviest(w, 8, never, 1));
        assertEquals(3, never.polls());
        AbortAt third = new AbortAt(3);
        assertEquals(-1, Likelihood.heaviest(w, 8, third, 1));
        assertEquals(3, third.polls());
    }

    private static double score(double x, double y, double th, double[] a) {
        double s = 1;
        for (double angle : a) {
            s *= Likelihood.of(x, y, th, angle, P);
        }
        return s;
    }
}
