package org.jmclbench.tooling.attribution;

import java.util.Arrays;

/**
 * Summary statistics of a sample of nanosecond values with summary.json's definitions
 * (docs/FORMATS.md section 4), so that a warm/steady split reads like the run's own summary:
 * percentiles are nearest-rank (the sorted value at index ceil(q * count) - 1, computed in
 * integers so that no rounding of q * count can move the rank); stdev is the population's.
 *
 * @param mean NaN when count is 0, as is stdev; the order statistics are then 0
 */
public record SampleStats(int count, double mean, double stdev, long min, long p50, long p90, long p99, long p999,
                          long max) {

    /** The statistics of {@code values} (not modified). */
    public static SampleStats of(long[] values) {
        int n = values.length;
        if (n == 0) {
            return new SampleStats(0, Double.NaN, Double.NaN, 0, 0, 0, 0, 0, 0);
        }
        long[] v = values.clone();
        Arrays.sort(v);
        double sum = 0;
        for (long x : v) {
            sum += x;
        }
        double mean = sum / n;
        double sq = 0;
        for (long x : v) {
            double d = x - mean;
            sq += d * d;
        }
        return new SampleStats(n, mean, Math.sqrt(sq / n), v[0], rank(v, 500), rank(v, 900), rank(v, 990), rank(v, 999),
                v[n - 1]);
    }

    /** Nearest rank for q = perMille / 1000 of a sorted, non-empty sample. */
    static long rank(long[] sorted, int perMille) {
        long n = sorted.length;
        int i = (int) ((perMille * n + 999) / 1000) - 1;
        return sorted[Math.max(0, Math.min(sorted.length - 1, i))];
    }
}
