package org.jmclbench.tooling.attribution;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.SplittableRandom;

import org.jmclbench.workload.record.Stats;
import org.junit.jupiter.api.Test;

/**
 * The warm/steady split's statistics are summary.json's: held equal to the workload's own
 * {@link Stats} (which writes summary.json) on random samples of every small size.
 */
class SampleStatsTest {

    @Test
    void sameAsTheWorkloadsSummaryStatistics() {
        SplittableRandom rng = new SplittableRandom(7);
        int compared = 0;
        for (int n = 0; n <= 2100; n += n < 40 ? 1 : 97) {
            long[] v = new long[n];
            for (int i = 0; i < n; i++) {
                v[i] = rng.nextLong(50_000_000L);
            }
            SampleStats mine = SampleStats.of(v);
            Stats theirs = Stats.of(v, n);
            String at = "n=" + n;
            assertEquals(theirs.count, mine.count(), at);
            assertEquals(theirs.mean, mine.mean(), 0.0, at);
            assertEquals(theirs.stdev, mine.stdev(), 0.0, at);
            assertEquals(theirs.min, mine.min(), at);
            assertEquals(theirs.p50, mine.p50(), at);
            assertEquals(theirs.p90, mine.p90(), at);
            assertEquals(theirs.p99, mine.p99(), at);
            assertEquals(theirs.p999, mine.p999(), at);
            assertEquals(theirs.max, mine.max(), at);
            compared++;
        }
        assertTrue(compared > 50);
    }

    @Test
    void nearestRankTakesTheValueAtCeilingOfQTimesCount() {
        long[] ten = {10, 1, 9, 2, 8, 3, 7, 4, 6, 5};
        assertEquals(9, SampleStats.of(ten).p90());
        assertEquals(5, SampleStats.of(ten).p50());
        assertEquals(10, SampleStats.of(ten).p99());
        long[] thousand = new long[1000];
        for (int i = 0; i < 1000; i++) {
            thousand[i] = 1000 - i;
        }
        assertEquals(999, SampleStats.of(thousand).p999());
        assertEquals(990, SampleStats.of(thousand).p99());
        assertTrue(Double.isNaN(SampleStats.of(new long[0]).mean()));
    }
}
