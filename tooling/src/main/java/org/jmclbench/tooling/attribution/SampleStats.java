package org.jmclbench.tooling.attribution;

import org.jmclbench.workload.record.Stats;

/**
 * Summary statistics of a sample of nanosecond values with summary.json's definitions
 * (docs/FORMATS.md section 4), so that a warm/steady split reads like the run's own summary:
 * computed by the workload's own {@link Stats} (nearest-rank percentiles, the population's
 * stdev), as a record.
 *
 * @param mean NaN when count is 0, as is stdev; the order statistics are then 0
 */
public record SampleStats(int count, double mean, double stdev, long min, long p50, long p90, long p99, long p999,
                          long max) {

    /** The statistics of {@code values} (not modified). */
    public static SampleStats of(long[] values) {
        Stats s = Stats.of(values, values.length);
        return new SampleStats(s.count, s.mean, s.stdev, s.min, s.p50, s.p90, s.p99, s.p999, s.max);
    }
}
