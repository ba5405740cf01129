package org.jmclbench.tooling.runner;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.HashSet;
import java.util.List;
import java.util.Random;
import java.util.Set;

import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import org.junit.jupiter.api.Test;

/** The breakdown-load search against fake outcome functions: no runs, no timing. */
class CapacitySearchTest {

    /** What every finished search promises, whatever the outcomes were. */
    private static void assertInvariants(CapacitySearch s, int from, int max) {
        assertTrue(s.done());
        List<CapacitySearch.Probe> probes = s.probes();
        Set<Integer> seen = new HashSet<>();
        for (CapacitySearch.Probe p : probes) {
            assertTrue(seen.add(p.particles()), "probed twice: " + p.particles());
            assertTrue(p.particles() >= from && p.particles() <= max, "out of range: " + p.particles());
        }
        assertTrue(probes.size() <= CapacitySearch.maxProbes(from, max), probes.size() + " probes");
        if (s.low() != null) {
            assertTrue(probes.contains(new CapacitySearch.Probe(s.low(), null)), "low held");
        }
        if (s.high() != null) {
            assertTrue(probes.contains(new CapacitySearch.Probe(s.high(), "failed")), "high failed");
        }
        if (s.status() == CapacitySearch.Status.BRACKETED) {
            assertTrue(s.low() < s.high());
            assertTrue(s.high() <= s.low() * 1.10 || s.high() - s.low() == 1, s.low() + ".." + s.high());
        }
    }

    @ParameterizedTest
    @ValueSource(ints = {101, 150, 399, 400, 401, 1000, 12800, 12801, 30000, 99999})
    void aMonotoneLoadIsBracketedWithinTenPercentAroundItsBreakdown(int breakdown) {
        // holds strictly below the breakdown count
        CapacitySearch s = CapacitySearch.run(100, 102400, n -> n < breakdown);
        assertEquals(CapacitySearch.Status.BRACKETED, s.status());
        assertTrue(s.low() < breakdown && s.high() >= breakdown, s.low() + ".." + s.high() + " around " + breakdown);
        assertInvariants(s, 100, 102400);
    }

    @Test
    void doublesThenBisectsAtTheGeometricMean() {
        CapacitySearch s = CapacitySearch.run(100, 102400, n -> n < 1000);
        List<Integer> counts = s.probes().stream().map(CapacitySearch.Probe::particles).toList();
        // 100, 200, 400, 800 hold; 1600 fails; sqrt(800 * 1600) = 1131 fails; sqrt(800 * 1131) = 951 holds; 1037 fails
        assertEquals(List.of(100, 200, 400, 800, 1600, 1131, 951, 1037), counts);
        assertEquals(951, s.low());
        assertEquals(1037, s.high());
        assertTrue(1037 <= 951 * 1.1);
        assertFalse(1037 <= 951 * 1.05, "and not needlessly tighter than asked");
    }

    @Test
    void failingAtTheSmallestCountEndsAtOnceWithNoLow() {
        CapacitySearch s = CapacitySearch.run(100, 102400, n -> false);
        assertEquals(CapacitySearch.Status.FAILS_AT_FROM, s.status());
        assertNull(s.low());
        assertEquals(100, s.high());
        assertEquals(1, s.probes().size());
    }

    @Test
    void neverFailingUpToMaxEndsAtMaxWithNoHigh() {
        CapacitySearch s = CapacitySearch.run(100, 1000, n -> true);
        assertEquals(CapacitySearch.Status.HOLDS_TO_MAX, s.status());
        assertEquals(1000, s.low());
        assertNull(s.high());
        // 100, 200, 400, 800, then max itself rather than 1600
        assertEquals(List.of(100, 200, 400, 800, 1000), s.probes().stream().map(CapacitySearch.Probe::particles).toList());
    }

    @Test
    void failingOnlyAtMaxBracketsBelowIt() {
        CapacitySearch s = CapacitySearch.run(100, 1000, n -> n < 1000);
        assertEquals(CapacitySearch.Status.BRACKETED, s.status());
        assertEquals(1000, s.high());
        assertInvariants(s, 100, 1000);
    }

    @Test
    void fromEqualToMaxIsOneProbe() {
        assertEquals(CapacitySearch.Status.HOLDS_TO_MAX, CapacitySearch.run(500, 500, n -> true).status());
        assertEquals(CapacitySearch.Status.FAILS_AT_FROM, CapacitySearch.run(500, 500, n -> false).status());
    }

    @Test
    void smallCountsStopAtAdjacentIntegers() {
        CapacitySearch s = CapacitySearch.run(1, 64, n -> n < 5);
        assertEquals(4, s.low());
        assertEquals(5, s.high());
        assertInvariants(s, 1, 64);
    }

    @Test
    void noisyOutcomesStillEndInAValidBracket() {
        // near the breakdown each probe fails at random (one repetition in three, say): the search
        // must still end, probe no count twice, and report a count that held and one that failed
        for (long seed = 0; seed < 200; seed++) {
            Random rnd = new Random(seed);
            CapacitySearch s = CapacitySearch.run(100, 102400, n -> n < 3000 || n < 6000 && rnd.nextInt(3) != 0);
            assertInvariants(s, 100, 102400);
            assertEquals(CapacitySearch.Status.BRACKETED, s.status());
            assertTrue(s.high() < 6000 * 1.1 && s.low() < 6000, "seed " + seed + ": " + s.low() + ".." + s.high());
        }
    }

    @Test
    void aProbeTheSearchDidNotAskForIsRefused() {
        CapacitySearch s = new CapacitySearch(100, 1000);
        assertThrows(IllegalStateException.class, () -> s.record(200, null));
        assertThrows(IllegalArgumentException.class, () -> new CapacitySearch(0, 10));
        assertThrows(IllegalArgumentException.class, () -> new CapacitySearch(100, 50));
    }
}
