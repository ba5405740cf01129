package org.jmclbench.tooling.report;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/** The one rule that tells two samples apart, on samples whose answer is known. */
class SeparationTest {

    private static double[] range(double from, int n) {
        double[] x = new double[n];
        for (int i = 0; i < n; i++) {
            x[i] = from + i;
        }
        return x;
    }

    @Test
    void theIssuesCaseNoMissAgainstOneMissInThreeRunsIsNotSeparated() {
        // Figure 3 of the old evaluation ranked C above the HVM on 0.0 against 0.3 misses, n = 3
        Separation.Result r = Separation.of(new double[] {0, 0, 0}, new double[] {0, 0, 1});
        assertEquals(Separation.Verdict.TOO_FEW, r.verdict());
        assertFalse(r.separated());
        assertTrue(r.text("native", "hvm").startsWith("not separated: n too small to separate ("), r.text("native", "hvm"));
        assertTrue(r.text("native", "hvm").endsWith("n = 3 vs 3; 10 a side needed)"), r.text("native", "hvm"));
    }

    @Test
    void evenAPerfectSplitOfThreeAgainstThreeIsTooFew() {
        Separation.Result r = Separation.of(new double[] {1, 2, 3}, new double[] {4, 5, 6});
        assertEquals(Separation.Verdict.TOO_FEW, r.verdict());
        assertEquals("not separated: n too small to separate (p = 0.100, n = 3 vs 3; 10 a side needed)", r.text("A", "B"));
        assertEquals("not separated: n too small to separate (n = 2 vs 3; 10 a side needed)",
                Separation.of(new double[] {1, 2}, new double[] {4, 5, 6}).text("A", "B"));
    }

    @Test
    void tenAgainstTenWithoutOverlapIsSeparatedAndSaysWhichIsLower() {
        Separation.Result r = Separation.of(range(1, 10), range(11, 10));
        assertEquals(Separation.Verdict.A_LOWER, r.verdict());
        assertTrue(r.separated());
        assertEquals(2.0 / 184_756, r.p(), 1e-12, "exact: 2 / choose(20, 10)");
        assertEquals("native lower than temurin-25 (p < 0.001, n = 10 vs 10)", r.text("native", "temurin-25"));

        Separation.Result back = Separation.of(range(11, 12), range(1, 10));
        assertEquals(Separation.Verdict.B_LOWER, back.verdict());
        assertEquals("native lower than temurin-25 (p < 0.001, n = 10 vs 12)", back.text("temurin-25", "native"));
    }

    @Test
    void interleavedSamplesAreNotSeparated() {
        Separation.Result r = Separation.of(range(1, 10), range(1.5, 10));
        assertEquals(Separation.Verdict.NOT_SEPARATED, r.verdict());
        assertTrue(r.p() > 0.5, "p " + r.p());
        assertTrue(r.text("A", "B").matches("not separated \\(p = 0\\.\\d{3}, n = 10 vs 10\\)"), r.text("A", "B"));
    }

    @Test
    void noMissOnEitherSideIsNotSeparated() {
        Separation.Result r = Separation.of(new double[10], new double[10]);
        assertEquals(Separation.Verdict.NOT_SEPARATED, r.verdict());
        assertEquals("not separated (p = 1.000, n = 10 vs 10)", r.text("A", "B"));
    }

    @Test
    void noMissAgainstSomeMissesInTenRunsEachIsSeparated() {
        double[] misses = {0, 1, 1, 2, 1, 0, 3, 1, 1, 2};
        Separation.Result r = Separation.of(new double[10], misses);
        assertEquals(Separation.Verdict.A_LOWER, r.verdict(), r.toString());
        assertTrue(Double.isInfinite(r.ratio().low()), "B/A is infinite when A never missed: " + r.ratio());
    }

    @Test
    void aSignificantTestIsNotEnoughWhenTheMeansDoNotDiffer() {
        // B is above A in 90 of 100 pairs, but A's one outlier makes its mean the larger: the
        // ratio's interval straddles 1, so the rule does not call either lower
        double[] a = {1, 1, 1, 1, 1, 1, 1, 1, 1, 100};
        double[] b = {2, 2, 2, 2, 2, 2, 2, 2, 2, 2};
        Separation.Result r = Separation.of(a, b);
        assertTrue(r.p() < Stats.ALPHA, "the test alone would separate: p " + r.p());
        assertFalse(r.ratio().excludesOne(), r.ratio().toString());
        assertEquals(Separation.Verdict.NOT_SEPARATED, r.verdict());
        assertTrue(r.text("A", "B").endsWith("; the ratio's 95% interval includes 1)"), r.text("A", "B"));
    }

    @Test
    void aTestAndMeansPointingOppositeWaysAreSaidAsSuch() {
        // A is below B in 14 of 20 runs (the test: A lower, p 0.030), but its six runs of 1000 make its mean
        // 30 times B's, with a ratio interval wholly below 1: not separated, and not because the interval
        // includes 1, as compare printed beside "[0.020, 0.100]"
        double[] a = new double[20];
        java.util.Arrays.fill(a, 14, 20, 1000);
        double[] b = new double[20];
        java.util.Arrays.fill(b, 10);
        Separation.Result r = Separation.of(a, b);
        assertTrue(r.p() < Stats.ALPHA, "p " + r.p());
        assertTrue(r.ratio().high() < 1, r.ratio().toString());
        assertEquals(Separation.Verdict.NOT_SEPARATED, r.verdict());
        assertEquals("not separated (p = 0.030, n = 20 vs 20; the test and the ratio of means point opposite ways)",
                r.text("A", "B"));
    }
}
