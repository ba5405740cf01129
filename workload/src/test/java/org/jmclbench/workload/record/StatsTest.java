package org.jmclbench.workload.record;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/** Nearest-rank percentiles and moments (FORMATS 4). */
class StatsTest {
    @Test
    void nearestRankOnOneToAThousand() {
        long[] v = new long[1000];
        for (int i = 0; i < v.length; i++) {
            v[i] = 1000 - i; // unsorted input
        }
        Stats s = Stats.of(v, 1000);
        assertEquals(1000, s.count);
        assertEquals(1, s.min);
        assertEquals(500, s.p50);
        assertEquals(900, s.p90);
        assertEquals(990, s.p99);
        assertEquals(999, s.p999);
        assertEquals(1000, s.max);
        assertEquals(500.5, s.mean, 1e-12);
        assertEquals(Math.sqrt((1000.0 * 1000 - 1) / 12), s.stdev, 1e-9);
        assertEquals(1000, v[0], "input untouched");
    }

    @Test
    void smallSamplesAndTheCountArgument() {
        Stats one = Stats.of(new long[] {42, 7, 7}, 1);
        assertEquals(1, one.count);
        assertEquals(42, one.p50);
        assertEquals(42, one.p999);
        assertEquals(0.0, one.stdev);
        // ceil(0.5 * 3) - 1 = 1, ceil(0.9 * 3) - 1 = 2.
        Stats three = Stats.of(new long[] {30, 10, 20}, 3);
        assertEquals(20, three.p50);
        assertEquals(30, three.p90);
        // ceil(0.99 * 100) - 1 = 98: no floating-point rounding may move it.
        long[] hundred = new long[100];
        for (int i = 0; i < 100; i++) {
            hundred[i] = i + 1;
        }
        assertEquals(99, Stats.of(hundred, 100).p99);
        assertEquals(50, Stats.of(hundred, 100).p50);
        Stats empty = Stats.of(new long[0], 0);
        assertEquals(0, empty.count);
        assertTrue(Double.isNaN(empty.mean));
    }
}
