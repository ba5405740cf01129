package org.jmclbench.core.mcl;

/**
 * Resampling of normalised weights into particle indices (ALGORITHM 7.5). The variants taking
 * an {@link AbortSignal} poll it before each block of {@code pollMask + 1} steps (an output, or
 * systematic's pass over an old particle; {@link MotionModel#ABORT_BLOCK} for the variants without
 * a mask) and return false when aborted (the output is then partial and must be discarded).
 */
public final class Resampling {
    private Resampling() {
    }

    /**
     * Systematic (low-variance) resampling, O(N): {@code u} is the offset {@code uniform() / N}.
     * outIndex[m] becomes the index of the old particle that new particle m copies.
     */
    public static void systematic(double[] w, int n, double u, int[] outIndex) {
        systematic(w, n, u, outIndex, AbortSignal.NEVER);
    }

    /** {@link #systematic(double[], int, double, int[])} with abort polling; false when aborted. */
    public static boolean systematic(double[] w, int n, double u, int[] outIndex, AbortSignal abort) {
        return systematic(w, n, u, outIndex, abort, MotionModel.ABORT_BLOCK - 1);
    }

    /**
     * Systematic resampling polling the abort signal when {@code (step & pollMask) == 0}; false
     * when aborted. One loop walks both sequences: each step either passes an old particle or
     * places a new one, at most 2N - 1 steps. As two nested loops (place m; while t > c, pass one),
     * one placing could pass all N old particles between two polls.
     */
    public static boolean systematic(double[] w, int n, double u, int[] outIndex, AbortSignal abort, int pollMask) {
        double c = w[0];
        int i = 0;
        int m = 0;
        for (int step = 0; m < n; step++) {
            if ((step & pollMask) == 0 && abort.abortRequested()) {
                return false;
            }
            double t = u + (double) m / n;
            if (t > c && i < n - 1) {
                i++;
                c += w[i];
            } else {
                outIndex[m] = i;
                m++;
            }
        }
        return true;
    }

    /**
     * Multinomial resampling, O(N log N): one {@code rng.uniform()} per new particle, in order;
     * new particle m copies the smallest k with t < C_k (cumulative weights), or N-1.
     * Allocates a scratch array; timed code uses the variant taking one.
     */
    public static void multinomial(double[] w, int n, Rng rng, int[] outIndex) {
        multinomial(w, n, rng, outIndex, new double[n], AbortSignal.NEVER);
    }

    /** Multinomial resampling with a caller-provided cumulative scratch array (length >= n) and abort polling. */
    public static boolean multinomial(double[] w, int n, Rng rng, int[] outIndex, double[] cumulative,
            AbortSignal abort) {
        return multinomial(w, n, rng, outIndex, cumulative, abort, MotionModel.ABORT_BLOCK - 1);
    }

    /** Multinomial resampling polling the abort signal when {@code (m & pollMask) == 0}; false when aborted. */
    public static boolean multinomial(double[] w, int n, Rng rng, int[] outIndex, double[] cumulative,
            AbortSignal abort, int pollMask) {
        double c = 0.0;
        for (int k = 0; k < n; k++) {
            if ((k & pollMask) == 0 && abort.abortRequested()) {
                return false;
            }
            c += w[k];
            cumulative[k] = c;
        }
        for (int m = 0; m < n; m++) {
            if ((m & pollMask) == 0 && abort.abortRequested()) {
                return false;
            }
            outIndex[m] = smallestAbove(cumulative, n, rng.uniform());
        }
        return true;
    }

    /** The smallest k with t < cumulative[k] (cumulative is non-decreasing), or n-1 when there is none. */
    static int smallestAbove(double[] cumulative, int n, double t) {
        int lo = 0;
        int hi = n - 1;
        if (!(t < cumulative[hi])) {
            return n - 1;
        }
        while (lo < hi) {
            int mid = (lo + hi) >>> 1;
            if (t < cumulative[mid]) {
                hi = mid;
            } else {
                lo = mid + 1;
            }
        }
        return lo;
    }
}
