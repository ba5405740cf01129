package org.jmclbench.tooling.report;

import java.util.Arrays;
import java.util.SplittableRandom;

import org.apache.commons.math3.distribution.TDistribution;
import org.apache.commons.math3.stat.inference.MannWhitneyUTest;

/** Statistics over repetitions: mean with a t confidence interval, bootstrap ratio interval, Mann-Whitney U. */
public final class Stats {

    /** Confidence level of every interval in the report and in compare. */
    public static final double CONFIDENCE = 0.95;
    /** Significance level of the Mann-Whitney U test. */
    public static final double ALPHA = 0.05;
    /** Below this many samples on either side, no test is made ("n too small"). */
    public static final int MIN_SAMPLES_FOR_TEST = 3;
    /** Bootstrap resamples; with the fixed seed the interval is the same on every call. */
    public static final int BOOTSTRAP_RESAMPLES = 10_000;
    /** Fixed seed of the bootstrap, so that a report or a compare is reproducible. */
    public static final long BOOTSTRAP_SEED = 20120601L;

    private Stats() {
    }

    /** A mean with the half-width of its confidence interval (NaN when n < 2). */
    public record MeanCi(int n, double mean, double halfWidth) {
        public double low() {
            return mean - halfWidth;
        }

        public double high() {
            return mean + halfWidth;
        }
    }

    /** A ratio B/A with its bootstrap interval (NaN bounds when it cannot be made). */
    public record RatioCi(double ratio, double low, double high) {
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

    /** Mean and the 95% Student-t interval half-width over repetitions. */
    public static MeanCi meanCi(double[] xs) {
        int n = xs.length;
        double m = mean(xs);
        if (n < 2) {
            return new MeanCi(n, m, Double.NaN);
        }
        double t = new TDistribution(n - 1).inverseCumulativeProbability(1 - (1 - CONFIDENCE) / 2);
        return new MeanCi(n, m, t * stdev(xs) / Math.sqrt(n));
    }

    /**
     * Ratio of means B/A with a percentile-bootstrap interval: A and B are resampled
     * independently with replacement, {@link #BOOTSTRAP_RESAMPLES} times, with a fixed seed.
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
            double r = resampledMean(b, rng) / resampledMean(a, rng);
            if (!Double.isNaN(r)) {
                ratios[k++] = r;
            }
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
        return sorted[lo] + (pos - lo) * (sorted[hi] - sorted[lo]);
    }

    /**
     * Two-sided Mann-Whitney U p-value, or NaN below {@link #MIN_SAMPLES_FOR_TEST} samples on
     * either side (the caller says "n too small"). Identical samples give p = 1.
     */
    public static double mannWhitneyP(double[] a, double[] b) {
        if (a.length < MIN_SAMPLES_FOR_TEST || b.length < MIN_SAMPLES_FOR_TEST) {
            return Double.NaN;
        }
        if (allEqual(a, b)) {
            return 1.0; // every rank tied: no difference (commons-math would divide by zero)
        }
        return new MannWhitneyUTest().mannWhitneyUTest(a, b);
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
