package org.jmclbench.core.mcl;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/** Systematic and multinomial resampling (ALGORITHM 7.5). */
class ResamplingTest {
    @Test
    void systematicOnKnownWeightsAndOffset() {
        int[] out = new int[4];
        // t = 0.1, 0.35, 0.6, 0.85 against cumulative 0.5, 0.5, 0.75, 1.0.
        Resampling.systematic(new double[] {0.5, 0.0, 0.25, 0.25}, 4, 0.1, out);
        assertArrayEquals(new int[] {0, 0, 2, 3}, out);
        // A zero offset: t = 0, 0.2, ... ; t equal to a cumulative weight stays (the test is t > c).
        int[] out5 = new int[5];
        Resampling.systematic(new double[] {0.2, 0.0, 0.0, 0.0, 0.8}, 5, 0.0, out5);
        assertArrayEquals(new int[] {0, 0, 4, 4, 4}, out5);
        // Weights whose sum falls short of 1 by rounding never run past the last particle.
        Resampling.systematic(new double[] {0.1, 0.1, 0.1}, 3, 0.3333, out);
        assertEquals(2, out[2]);
    }

    @Test
    void systematicCountsAreWithinOneOfNTimesTheWeight() {
        int n = 1000;
        double[] w = weights(n);
        int[] out = new int[n];
        Rng rng = new Rng(7);
        for (int trial = 0; trial < 20; trial++) {
            Resampling.systematic(w, n, rng.uniform() / n, out);
            int[] count = new int[n];
            for (int m = 0; m < n; m++) {
                count[out[m]]++;
                assertTrue(m == 0 || out[m] >= out[m - 1], "indices are non-decreasing");
            }
            for (int i = 0; i < n; i++) {
                assertTrue(Math.abs(count[i] - n * w[i]) < 1.0 + 1e-9, "particle " + i + ": " + count[i]
                        + " copies for expected " + n * w[i]);
            }
        }
    }

    @Test
    void multinomialCountsFollowTheWeights() {
        int k = 10;
        int n = 100000;
        double[] small = new double[k];
        double sum = 0;
        for (int i = 0; i < k; i++) {
            small[i] = i + 1;
            sum += small[i];
        }
        // N particles in 10 groups; group g has weight proportional to g + 1.
        double[] w = new double[n];
        for (int i = 0; i < n; i++) {
            w[i] = small[i % k] / sum / (n / k);
        }
        int[] out = new int[n];
        Resampling.multinomial(w, n, new Rng(11), out);
        long[] groups = new long[k];
        for (int m = 0; m < n; m++) {
            groups[out[m] % k]++;
        }
        for (int g = 0; g < k; g++) {
            double p = small[g] / sum;
            double expected = n * p;
            double sd = Math.sqrt(n * p * (1 - p));
            assertEquals(expected, groups[g], 5 * sd, "group " + g);
        }
    }

    @Test
    void multinomialPicksTheSmallestCumulativeAboveTheDraw() {
        double[] c = {0.1, 0.1, 0.5, 0.9, 0.9, 1.0};
        assertEquals(0, Resampling.smallestAbove(c, 6, 0.0));
        assertEquals(2, Resampling.smallestAbove(c, 6, 0.1));
        assertEquals(2, Resampling.smallestAbove(c, 6, 0.49));
        assertEquals(3, Resampling.smallestAbove(c, 6, 0.5));
        assertEquals(5, Resampling.smallestAbove(c, 6, 0.9));
        // None above: the last particle.
        assertEquals(2, Resampling.smallestAbove(new double[] {0.3, 0.6, 0.9999}, 3, 0.99995));
        // Same result as the linear definition on random data.
        Rng rng = new Rng(3);
        int n = 257;
        double[] w = weights(n);
        double[] cum = new double[n];
        double s = 0;
        for (int i = 0; i < n; i++) {
            s += w[i];
            cum[i] = s;
        }
        for (int trial = 0; trial < 2000; trial++) {
            double t = rng.uniform();
            int linear = n - 1;
            for (int i = 0; i < n; i++) {
                if (t < cum[i]) {
                    linear = i;
                    break;
                }
            }
            assertEquals(linear, Resampling.smallestAbove(cum, n, t));
        }
    }

    @Test
    void anAbortedResamplingSaysSo() {
        int n = 200;
        double[] w = weights(n);
        assertFalse(Resampling.systematic(w, n, 0.001, new int[n], new AbortAt(2)));
        assertFalse(Resampling.multinomial(w, n, new Rng(1), new int[n], new double[n], new AbortAt(2)));
        assertTrue(Resampling.systematic(w, n, 0.001, new int[n], AbortSignal.NEVER));
    }

    /** Normalised, uneven weights (some zero). */
    static double[] weights(int n) {
        Rng rng = new Rng(5);
        double[] w = new double[n];
        double sum = 0;
        for (int i = 0; i < n; i++) {
            double u = rng.uniform();
            w[i] = u < 0.2 ? 0.0 : u * u;
            sum += w[i];
        }
        for (int i = 0; i < n; i++) {
            w[i] /= sum;
        }
        return w;
    }
}
