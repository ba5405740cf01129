package org.jmclbench.tooling.report;

import java.util.Arrays;
import java.util.Locale;
import java.util.SplittableRandom;

import org.apache.commons.math3.stat.inference.MannWhitneyUTest;

/**
 * Statistics over repetitions, with intervals that respect the quantity (docs/REPORT.md): a
 * percentile-bootstrap interval of a mean (never outside the sample's range, so never below
 * zero for a count or a latency), a Wilson score interval of a proportion (inside [0, 1]), a
 * bootstrap interval of a ratio of means, and the Mann-Whitney U test. {@link Separation}
 * combines them into the one rule that says whether two samples differ.
 */
public final class Stats {

    /** Confidence level of every interval in the report and in compare. */
    public static final double CONFIDENCE = 0.95;
    /** Significance level of the Mann-Whitney U test. */
    public static final double ALPHA = 0.05;
    /** Below this many samples on either side, no p-value is computed. */
    public static final int MIN_SAMPLES_FOR_TEST = 3;
    /** Bootstrap resamples; with the fixed seed the interval is the same on every call. */
    public static final int BOOTSTRAP_RESAMPLES = 10_000;
    /** Fixed seed of the bootstrap, so that a report or a compare is reproducible. */
    public static final long BOOTSTRAP_SEED = 20120601L;
    /** The standard normal quantile of 1 - (1 - CONFIDENCE) / 2 (Wilson's z). */
    static final double Z = 1.959963984540054;

    private Stats() {
    }

    /**
     * An estimate with its 95% interval [low, high]; NaN bounds where none can be made (one
     * repetition, no trial). The interval need not be symmetric about the estimate.
     */
    public record Interval(double estimate, double low, double high) {
        /** Whether the interval has finite bounds. */
        public boolean bounded() {
            return Double.isFinite(low) && Double.isFinite(high);
        }

        /** {@code estimate [low, high]} with {@code decimals} digits; the estimate alone without bounds. */
        public String text(int decimals) {
            String f = "%." + decimals + "f";
            String e = String.format(Locale.ROOT, f, estimate);
            return bounded() ? e + " [" + String.format(Locale.ROOT, f, low) + ", " + String.format(Locale.ROOT, f, high) + "]" : e;
        }
    }

    /** A ratio B/A with its bootstrap interval (NaN bounds when it cannot be made). */
    public record RatioCi(double ratio, double low, double high) {
        /** Whether the interval lies wholly on one side of 1 (B and A differ in their means). */
        public boolean excludesOne() {
            return !Double.isNaN(low) && !Double.isNaN(high) && (low > 1 || high < 1);
        }
    }

    public static double mean(double[] xs) {
        if (xs.length == 0) {
            return Double.NaN;
        }
        double s = 0;
        for (double x : xs) {
            s += x;
        }
        return s / xs.length;
    }

    /** Sample standard deviation (n - 1); NaN when n < 2. */
    public static double stdev(double[] xs) {
        int n = xs.length;
        if (n < 2) {
            return Double.NaN;
        }
        double m = mean(xs);
        double ss = 0;
        for (double x : xs) {
            ss += (x - m) * (x - m);
        }
        return Math.sqrt(ss / (n - 1));
    }

    /**
     * The mean over repetitions with its 95% percentile-bootstrap interval: the sample is
     * resampled with replacement {@link #BOOTSTRAP_RESAMPLES} times (fixed seed) and the interval
     * is the 2.5th and 97.5th percentiles of the resampled means. It lies within the sample's
     * range, so a count, a ratio or a latency never gets a negative bound (as a Student-t
     * interval does: 0, 0, 1 misses gave 0.3 ± 1.4). With fewer than 2 values, NaN bounds.
     */
    public static Interval bootstrapMean(double[] xs) {
        double m = mean(xs);
        if (xs.length < 2) {
            return new Interval(m, Double.NaN, Double.NaN);
        }
        if (allEqual(xs, xs)) {
            return new Interval(m, xs[0], xs[0]);
        }
        SplittableRandom rng = new SplittableRandom(BOOTSTRAP_SEED);
        double[] means = new double[BOOTSTRAP_RESAMPLES];
        for (int i = 0; i < BOOTSTRAP_RESAMPLES; i++) {
            means[i] = resampledMean(xs, rng);
        }
        Arrays.sort(means);
        double tail = (1 - CONFIDENCE) / 2;
        return new Interval(m, quantile(means, tail), quantile(means, 1 - tail));
    }

    /**
     * A proportion k/n (misses over released jobs, pooled over repetitions) with its 95% Wilson
     * score interval, which stays inside [0, 1] and is not degenerate at 0 or n (0 of 300 gives
     * [0, 0.0126], not [0, 0]). NaN everywhere when n is 0.
     */
    public static Interval wilson(long k, long n) {
        if (n <= 0 || k < 0 || k > n) {
            return new Interval(Double.NaN, Double.NaN, Double.NaN);
        }
        double p = (double) k / n;
        double z2 = Z * Z;
        double centre = (p + z2 / (2.0 * n)) / (1 + z2 / n);
        double half = Z / (1 + z2 / n) * Math.sqrt(p * (1 - p) / n + z2 / (4.0 * n * n));
        // at k = 0 (k = n) the bound is exactly 0 (1); the formula leaves a rounding residue
        return new Interval(p, k == 0 ? 0 : Math.max(0, centre - half), k == n ? 1 : Math.min(1, centre + half));
    }

    /**
     * Ratio of means B/A with a percentile-bootstrap interval: A and B are resampled
     * independently with replacement, {@link #BOOTSTRAP_RESAMPLES} times, with a fixed seed. A
     * resample in which both means are 0 (no miss on either side) counts as a ratio of 1, no
     * difference; one with only A's mean 0 as +infinity.
     */
    public static RatioCi ratioCi(double[] a, double[] b) {
        double ratio = mean(b) / mean(a);
        if (a.length < 2 || b.length < 2) {
            return new RatioCi(ratio, Double.NaN, Double.NaN);
        }
        SplittableRandom rng = new SplittableRandom(BOOTSTRAP_SEED);
        double[] ratios = new double[BOOTSTRAP_RESAMPLES];
        int k = 0;
        for (int i = 0; i < BOOTSTRAP_RESAMPLES; i++) {
            double mb = resampledMean(b, rng);
            double ma = resampledMean(a, rng);
            ratios[k++] = ma == 0 && mb == 0 ? 1.0 : mb / ma;
        }
        if (k == 0) {
            return new RatioCi(ratio, Double.NaN, Double.NaN);
        }
        double[] valid = Arrays.copyOf(ratios, k);
        Arrays.sort(valid);
        double tail = (1 - CONFIDENCE) / 2;
        return new RatioCi(ratio, quantile(valid, tail), quantile(valid, 1 - tail));
    }

    private static double resampledMean(double[] xs, SplittableRandom rng) {
        double s = 0;
        for (int i = 0; i < xs.length; i++) {
            s += xs[rng.nextInt(xs.length)];
        }
        return s / xs.length;
    }

    /** Linear-interpolated quantile of a sorted sample. */
    static double quantile(double[] sorted, double q) {
        double pos = q * (sorted.length - 1);
        int lo = (int) Math.floor(pos);
        int hi = Math.min(lo + 1, sorted.length - 1);
        if (pos == lo || sorted[hi] == sorted[lo]) {
            return sorted[lo]; // also keeps an infinite ratio infinite (inf - inf would be NaN)
        }
        return sorted[lo] + (pos - lo) * (sorted[hi] - sorted[lo]);
    }

    /** Below this many samples in all, without ties, the p-value is exact (as R's wilcox.test does). */
    public static final int EXACT_BELOW = 50;

    /**
     * Two-sided Mann-Whitney U p-value, or NaN below {@link #MIN_SAMPLES_FOR_TEST} samples on
     * either side (the caller says "n too small"). Small samples without ties get the exact
     * distribution of U (the normal approximation would call 3 runs against 3 significant, which
     * the exact test never can: its smallest p is 0.1); others commons-math's normal
     * approximation. Identical samples give p = 1.
     */
    public static double mannWhitneyP(double[] a, double[] b) {
        if (a.length < MIN_SAMPLES_FOR_TEST || b.length < MIN_SAMPLES_FOR_TEST) {
            return Double.NaN;
        }
        if (allEqual(a, b)) {
            return 1.0; // every rank tied: no difference (commons-math would divide by zero)
        }
        if (a.length + b.length < EXACT_BELOW && !hasTies(a, b)) {
            return exactMannWhitneyP(a, b);
        }
        return new MannWhitneyUTest().mannWhitneyUTest(a, b);
    }

    /** U of a: the number of pairs (x in a, y in b) with x > y (no ties). */
    static long u(double[] a, double[] b) {
        long u = 0;
        for (double x : a) {
            for (double y : b) {
                if (x > y) {
                    u++;
                }
            }
        }
        return u;
    }

    /** Exact two-sided p: 2 P(U <= min(U, mn - U)) under H0, from the counts of rank arrangements. */
    static double exactMannWhitneyP(double[] a, double[] b) {
        int m = a.length;
        int n = b.length;
        long ua = u(a, b);
        long umin = Math.min(ua, (long) m * n - ua);
        // count[i][j][u]: arrangements of i a's and j b's with U = u; f(u; i, j) = f(u - j; i-1, j) + f(u; i, j-1)
        double[][] prev = new double[n + 1][];
        for (int j = 0; j <= n; j++) {
            prev[j] = new double[] {1}; // i = 0: U is 0 in one way
        }
        for (int i = 1; i <= m; i++) {
            double[][] cur = new double[n + 1][];
            cur[0] = new double[] {1};
            for (int j = 1; j <= n; j++) {
                double[] f = new double[i * j + 1];
                double[] left = prev[j];      // i-1, j: shifted by j (the new a beats all j b's)
                double[] down = cur[j - 1];   // i, j-1
                for (int u = 0; u < f.length; u++) {
                    double v = 0;
                    if (u - j >= 0 && u - j < left.length) {
                        v += left[u - j];
                    }
                    if (u < down.length) {
                        v += down[u];
                    }
                    f[u] = v;
                }
                cur[j] = f;
            }
            prev = cur;
        }
        double[] dist = prev[n];
        double total = 0;
        double tail = 0;
        for (int u = 0; u < dist.length; u++) {
            total += dist[u];
            if (u <= umin) {
                tail += dist[u];
            }
        }
        return Math.min(1.0, 2 * tail / total);
    }

    private static boolean hasTies(double[] a, double[] b) {
        double[] all = new double[a.length + b.length];
        System.arraycopy(a, 0, all, 0, a.length);
        System.arraycopy(b, 0, all, a.length, b.length);
        Arrays.sort(all);
        for (int i = 1; i < all.length; i++) {
            if (all[i] == all[i - 1]) {
                return true;
            }
        }
        return false;
    }

    private static boolean allEqual(double[] a, double[] b) {
        double v = a[0];
        for (double x : a) {
            if (x != v) {
                return false;
            }
        }
        for (double x : b) {
            if (x != v) {
                return false;
            }
        }
        return true;
    }
}
