package org.jmclbench.tooling.report;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/** The statistics against values computed by hand or by R on known samples. */
class StatsTest {

    @Test
    void meanAndStudentTInterval() {
        Stats.MeanCi ci = Stats.meanCi(new double[] {1, 2, 3, 4, 5});
        assertEquals(3.0, ci.mean(), 1e-12);
        // t(0.975, 4) = 2.776445; s = sqrt(2.5); half = t * s / sqrt(5)
        assertEquals(2.776445 * Math.sqrt(2.5) / Math.sqrt(5), ci.halfWidth(), 1e-5);
        assertEquals(1.036757, ci.low(), 1e-5);
        assertTrue(Double.isNaN(Stats.meanCi(new double[] {7}).halfWidth()), "one sample has no interval");
        assertEquals(0.0, Stats.meanCi(new double[] {4, 4, 4}).halfWidth(), 0.0);
    }

    @Test
    void mannWhitneyIsExactForSmallSamplesWithoutTies() {
        // R: wilcox.test(c(1,2,3), c(4,5,6))$p.value = 0.1 (exact; the normal approximation says 0.0495)
        assertEquals(0.1, Stats.mannWhitneyP(new double[] {1, 2, 3}, new double[] {4, 5, 6}), 1e-12);
        // R: wilcox.test(c(1,2,3,4), c(5,6,7,8))$p.value = 0.02857143 (2 / choose(8, 4))
        assertEquals(2.0 / 70, Stats.mannWhitneyP(new double[] {1, 2, 3, 4}, new double[] {5, 6, 7, 8}), 1e-12);
        // Against a brute-force enumeration of every split of the 15 ranks into 10 and 5.
        double[] x = {1.83, 0.50, 1.62, 2.48, 1.68, 1.88, 1.55, 3.06, 1.30, 1.5};
        double[] y = {0.878, 0.647, 0.598, 2.05, 1.06};
        assertEquals(38, Stats.u(x, y), "x beats y in 9 + 9 + 9 + 2 + 9 pairs");
        assertEquals(bruteForceP(10, 5, 38), Stats.mannWhitneyP(x, y), 1e-12);
        assertEquals(bruteForceP(10, 5, 38), Stats.mannWhitneyP(y, x), 1e-12, "symmetric");
    }

    /** Two-sided exact p by listing every subset of ranks 0..m+n-1 that the first sample can hold. */
    private static double bruteForceP(int m, int n, long observedU) {
        long umin = Math.min(observedU, (long) m * n - observedU);
        int total = 0;
        int tail = 0;
        for (int mask = 0; mask < 1 << (m + n); mask++) {
            if (Integer.bitCount(mask) != m) {
                continue;
            }
            long u = 0;
            for (int i = 0; i < m + n; i++) {
                if ((mask & 1 << i) != 0) {
                    for (int j = 0; j < i; j++) {
                        if ((mask & 1 << j) == 0) {
                            u++; // this a is above that b
                        }
                    }
                }
            }
            total++;
            if (u <= umin) {
                tail++;
            }
        }
        return Math.min(1.0, 2.0 * tail / total);
    }

    @Test
    void mannWhitneyWithTiesUsesTheNormalApproximation() {
        // a = {1,2,3,3}, b = {3,4,5,6}: the three 3s share rank 4, R1 = 1+2+4+4 = 11, U = 11 - 10 = 1,
        // mu = 8, sigma = sqrt(4 * 4 * 9 / 12); p = 2 * pnorm((1 - 8) / sigma) (no tie correction)
        double z = (1 - 8) / Math.sqrt(4 * 4 * 9 / 12.0);
        double expected = 2 * new org.apache.commons.math3.distribution.NormalDistribution().cumulativeProbability(z);
        assertEquals(expected, Stats.mannWhitneyP(new double[] {1, 2, 3, 3}, new double[] {3, 4, 5, 6}), 1e-9);
        assertEquals(0.0433, expected, 1e-4);
    }

    @Test
    void mannWhitneyNeedsThreeSamplesEachAndTreatsIdenticalSamplesAsEqual() {
        assertTrue(Double.isNaN(Stats.mannWhitneyP(new double[] {1, 2}, new double[] {3, 4, 5})));
        assertEquals(1.0, Stats.mannWhitneyP(new double[] {2, 2, 2}, new double[] {2, 2, 2}), 0.0);
        assertEquals("n too small", CompareCommand.compare(new double[] {1, 2}, new double[] {3, 4, 5}).verdict());
        assertTrue(CompareCommand.compare(new double[] {1, 2, 3}, new double[] {4, 5, 6}).verdict().startsWith("~ not significant"),
                "three against three can never be significant (exact p >= 0.1)");
        assertTrue(CompareCommand.compare(new double[] {1, 2, 3, 4}, new double[] {5, 6, 7, 8}).verdict().startsWith("significant"));
        assertTrue(CompareCommand.compare(new double[] {1, 5, 3}, new double[] {4, 2, 6}).verdict().startsWith("~ not significant"));
    }

    @Test
    void bootstrapRatioIntervalIsExactForConstantsAndReproducible() {
        Stats.RatioCi c = Stats.ratioCi(new double[] {2, 2, 2, 2}, new double[] {5, 5, 5});
        assertEquals(2.5, c.ratio(), 1e-12);
        assertEquals(2.5, c.low(), 1e-12);
        assertEquals(2.5, c.high(), 1e-12);

        double[] a = {10, 11, 9, 10, 12, 8, 10, 11};
        double[] b = new double[a.length];
        for (int i = 0; i < a.length; i++) {
            b[i] = 1.5 * a[i];
        }
        Stats.RatioCi r = Stats.ratioCi(a, b);
        assertEquals(1.5, r.ratio(), 1e-12);
        assertTrue(r.low() < 1.5 && r.high() > 1.5, "interval around the ratio: " + r);
        assertTrue(r.low() > 1.2 && r.high() < 1.8, "interval of plausible width: " + r);
        assertEquals(r, Stats.ratioCi(a, b), "fixed seed: the same interval every time");
        assertTrue(Double.isNaN(Stats.ratioCi(new double[] {1}, b).low()), "one sample: no interval");
    }

    @Test
    void quantileInterpolates() {
        double[] s = {1, 2, 3, 4};
        assertEquals(1.0, Stats.quantile(s, 0), 0);
        assertEquals(2.5, Stats.quantile(s, 0.5), 1e-12);
        assertEquals(4.0, Stats.quantile(s, 1), 0);
    }
}
