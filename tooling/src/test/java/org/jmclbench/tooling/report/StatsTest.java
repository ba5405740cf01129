package org.jmclbench.tooling.report;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/** The statistics against values computed by hand or by R on known samples. */
class StatsTest {

    @Test
    void theBootstrapIntervalOfAMeanNeverLeavesTheSampleRange() {
        // the case: 0, 0, 1 misses was 0.3 ± 1.4 with Student's t, i.e. down to -1.1 misses
        Stats.Interval misses = Stats.bootstrapMean(new double[] {0, 0, 1});
        assertEquals(1.0 / 3, misses.estimate(), 1e-12);
        assertEquals(0.0, misses.low(), 0.0, "the lowest resampled mean is 0, never below");
        assertEquals(1.0, misses.high(), 1e-12, "3 ones in a row happen in 1 of 27 resamples, above the 2.5% tail");
        assertEquals("0.3 [0.0, 1.0]", misses.text(1));

        double[] latency = {1.1, 1.3, 0.9, 1.2, 1.0, 1.25, 0.95, 1.05, 1.15, 1.1};
        Stats.Interval l = Stats.bootstrapMean(latency);
        assertTrue(l.low() > 0.9 && l.low() < l.estimate() && l.estimate() < l.high() && l.high() < 1.3, l.toString());
        // the bootstrap's width is about the t interval's for well-behaved data: 2 * 1.96 * s / sqrt(n)
        double expected = 2 * 1.96 * Stats.stdev(latency) / Math.sqrt(latency.length);
        assertEquals(expected, l.high() - l.low(), 0.25 * expected);
        assertEquals(l, Stats.bootstrapMean(latency), "fixed seed: the same interval every time");

        assertEquals(new Stats.Interval(4, 4, 4), Stats.bootstrapMean(new double[] {4, 4, 4}));
        assertTrue(Double.isNaN(Stats.bootstrapMean(new double[] {7}).low()), "one sample has no interval");
        assertEquals("7.00", Stats.bootstrapMean(new double[] {7}).text(2));
    }

    @Test
    void theWilsonIntervalOfAProportionStaysInZeroOneAndIsNotDegenerateAtZero() {
        Stats.Interval none = Stats.wilson(0, 300);
        assertEquals(0.0, none.estimate(), 0.0);
        assertEquals(0.0, none.low(), 0.0);
        // z^2 / (n + z^2) at k = 0
        assertEquals(Stats.Z * Stats.Z / (300 + Stats.Z * Stats.Z), none.high(), 1e-12);
        // 5 of 100: [0.02154, 0.11175] (Wilson 1927; R: binom::binom.wilson)
        Stats.Interval five = Stats.wilson(5, 100);
        assertEquals(0.05, five.estimate(), 1e-12);
        assertEquals(0.02154, five.low(), 5e-5);
        assertEquals(0.11175, five.high(), 5e-5);
        Stats.Interval all = Stats.wilson(40, 40);
        assertEquals(1.0, all.high(), 0.0);
        assertTrue(all.low() > 0.9 && all.low() < 1, all.toString());
        assertTrue(Double.isNaN(Stats.wilson(0, 0).estimate()), "no trial, no proportion");
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
        assertEquals("not separated: n too small to separate (n = 2 vs 3; 10 a side needed)",
                CompareCommand.compare(new double[] {1, 2}, new double[] {3, 4, 5}).verdict());

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

        // no miss on either side: no difference, not an undefined interval
        Stats.RatioCi zeros = Stats.ratioCi(new double[] {0, 0, 0}, new double[] {0, 0, 0});
        assertEquals(1.0, zeros.low(), 0.0);
        assertEquals(1.0, zeros.high(), 0.0);
        assertTrue(!zeros.excludesOne());
        assertTrue(Stats.ratioCi(new double[] {0, 0, 0, 0}, new double[] {3, 4, 5, 6}).excludesOne(), "0 against 3 to 6 misses");
    }

    @Test
    void quantileInterpolates() {
        double[] s = {1, 2, 3, 4};
        assertEquals(1.0, Stats.quantile(s, 0), 0);
        assertEquals(2.5, Stats.quantile(s, 0.5), 1e-12);
        assertEquals(4.0, Stats.quantile(s, 1), 0);
    }
}
