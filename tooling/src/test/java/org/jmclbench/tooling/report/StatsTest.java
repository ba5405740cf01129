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
    void mannWhitneyMatchesTheNormalApproximation() {
        // R: wilcox.test(c(1,2,3), c(4,5,6), exact=FALSE, correct=FALSE)$p.value = 0.04953461
        assertEquals(0.04953461, Stats.mannWhitneyP(new double[] {1, 2, 3}, new double[] {4, 5, 6}), 1e-6);
        // Counted by hand: x beats y in 9 + 9 + 9 + 2 + 9 = 38 of the 50 pairs, so U = 38, mu = 25,
        // sigma = sqrt(10 * 5 * 16 / 12), p = 2 * pnorm(-13 / sigma) = 0.1113469 (two-sided, no correction)
        double[] x = {1.83, 0.50, 1.62, 2.48, 1.68, 1.88, 1.55, 3.06, 1.30, 1.5};
        double[] y = {0.878, 0.647, 0.598, 2.05, 1.06};
        double sigma = Math.sqrt(10 * 5 * 16 / 12.0);
        double expected = 2 * new org.apache.commons.math3.distribution.NormalDistribution().cumulativeProbability(-(38 - 25) / sigma);
        assertEquals(expected, Stats.mannWhitneyP(x, y), 1e-9);
        assertEquals(0.1113469, Stats.mannWhitneyP(x, y), 1e-6);
    }

    @Test
    void mannWhitneyNeedsThreeSamplesEachAndTreatsIdenticalSamplesAsEqual() {
        assertTrue(Double.isNaN(Stats.mannWhitneyP(new double[] {1, 2}, new double[] {3, 4, 5})));
        assertEquals(1.0, Stats.mannWhitneyP(new double[] {2, 2, 2}, new double[] {2, 2, 2}), 0.0);
        assertEquals("n too small", CompareCommand.compare(new double[] {1, 2}, new double[] {3, 4, 5}).verdict());
        assertTrue(CompareCommand.compare(new double[] {1, 2, 3}, new double[] {4, 5, 6}).verdict().startsWith("significant"));
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
