package org.jmclbench.workload.record;

import java.util.Arrays;

/**
 * Summary statistics of a sample of nanosecond values (docs/FORMATS.md section 4): percentiles
 * are nearest-rank (the sorted value at index ceil(q * count) - 1); stdev is the population
 * standard deviation. Computed after the run, never while measuring.
 */
public final class Stats {
    public final int count;
    /** NaN when count is 0, as are stdev. */
    public final double mean;
    public final double stdev;
    /** The order statistics; 0 when count is 0 (writers print null: check count). */
    public final long min;
    public final long p50;
    public final long p90;
    public final long p99;
    public final long p999;
    public final long max;

    private Stats(int count, double mean, double stdev, long min, long p50, long p90, long p99, long p999,
            long max) {
        this.count = count;
        this.mean = mean;
        this.stdev = stdev;
        this.min = min;
        this.p50 = p50;
        this.p90 = p90;
        this.p99 = p99;
        this.p999 = p999;
        this.max = max;
    }

    /** Statistics of values[0..count-1] (the array is not modified). */
    public static Stats of(long[] values, int count) {
        if (count == 0) {
            return new Stats(0, Double.NaN, Double.NaN, 0, 0, 0, 0, 0, 0);
        }
        long[] v = Arrays.copyOf(values, count);
        Arrays.sort(v);
        double sum = 0;
        for (long x : v) {
            sum += x;
        }
        double mean = sum / count;
        double sq = 0;
        for (long x : v) {
            double d = x - mean;
            sq += d * d;
        }
        double stdev = Math.sqrt(sq / count);
        return new Stats(count, mean, stdev, v[0], rank(v, 500), rank(v, 900), rank(v, 990), rank(v, 999),
                v[count - 1]);
    }

    /**
     * Nearest rank for q = perMille / 1000: the value at index ceil(q * count) - 1, at least
     * index 0; in integers so that no rounding of q * count can move the rank.
     */
    static long rank(long[] sorted, int perMille) {
        long n = sorted.length;
        int i = (int) ((perMille * n + 999) / 1000) - 1;
        return sorted[Math.max(0, Math.min(sorted.length - 1, i))];
    }

    /** Stands for +infinity in {@link #rankOfReleases}: a release whose job never completed. */
    public static final long NOT_COMPLETED = Long.MAX_VALUE;

    /**
     * The nearest-rank value at q = perMille / 1000 of a sample of {@code released} values of which
     * the {@code completed} smallest are {@code sorted[0..completed-1]} and the rest are +infinity
     * (jobs dropped or aborted, which never answer): {@link #NOT_COMPLETED} when the rank falls
     * among those. Requires {@code 0 < released} and {@code completed <= released}.
     */
    public static long rankOfReleases(long[] sorted, int completed, int released, int perMille) {
        int i = (int) ((perMille * (long) released + 999) / 1000) - 1;
        i = Math.max(0, Math.min(released - 1, i));
        return i < completed ? sorted[i] : NOT_COMPLETED;
    }

    /** An empty sample's statistics. */
    public static Stats empty() {
        return of(new long[0], 0);
    }

    @Override
    public String toString() {
        return "Stats[count=" + count + ", mean=" + mean + ", stdev=" + stdev + ", min=" + min + ", p50=" + p50
                + ", p90=" + p90 + ", p99=" + p99 + ", p999=" + p999 + ", max=" + max + "]";
    }
}
