package org.jmclbench.tooling.report;

import java.util.Locale;

/**
 * Whether two samples of repetitions (A and B, one value per run, lower is better for every
 * metric here) are told apart, by one rule used by compare, the report and the evaluation
 * (docs/REPORT.md): at least {@link #MIN_REPETITIONS} runs a side, the two-sided Mann-Whitney U
 * test at {@link Stats#ALPHA}, and the 95% bootstrap interval of the ratio of means B/A wholly
 * on one side of 1, on the same side as the test's direction. Anything else is "not separated";
 * too few runs is said as such. Never a ranking where the rule does not hold.
 */
public final class Separation {
    /**
     * Runs a side below which no conclusion is drawn. With 10 against 10 the exact test can reach
     * p = 1e-5 and a bootstrap interval has enough distinct resamples to mean something; with 3
     * against 3 the smallest possible p is 0.1, so nothing could ever separate.
     */
    public static final int MIN_REPETITIONS = 10;

    /** What the rule concluded. */
    public enum Verdict {
        /** A's values are lower than B's. */
        A_LOWER,
        /** B's values are lower than A's. */
        B_LOWER,
        /** Enough runs, but the test or the ratio interval does not separate them. */
        NOT_SEPARATED,
        /** Fewer than {@link #MIN_REPETITIONS} runs on a side: no conclusion either way. */
        TOO_FEW
    }

    /**
     * The outcome for A and B: the verdict, the Mann-Whitney p (NaN below
     * {@link Stats#MIN_SAMPLES_FOR_TEST} runs a side), the runs a side and the ratio of means B/A
     * with its bootstrap interval.
     */
    public record Result(Verdict verdict, double p, int nA, int nB, Stats.RatioCi ratio) {
        /** Whether one side is lower than the other by the rule. */
        public boolean separated() {
            return verdict == Verdict.A_LOWER || verdict == Verdict.B_LOWER;
        }

        /**
         * The wording the report and the evaluation use, e.g. {@code native lower than temurin-25
         * (p = 0.003, n = 10 vs 10)}, {@code not separated (p = 0.412, n = 10 vs 10)},
         * {@code not separated: n too small to separate (p = 0.100, n = 3 vs 3; 10 a side needed)}.
         */
        public String text(String nameA, String nameB) {
            return switch (verdict) {
                case A_LOWER -> nameA + " lower than " + nameB + " (" + pText() + ", n = " + nA + " vs " + nB + ")";
                case B_LOWER -> nameB + " lower than " + nameA + " (" + pText() + ", n = " + nB + " vs " + nA + ")";
                case NOT_SEPARATED -> "not separated (" + pText() + ", n = " + nA + " vs " + nB + reason() + ")";
                case TOO_FEW -> "not separated: n too small to separate (" + (Double.isNaN(p) ? "" : pText() + ", ")
                        + "n = " + nA + " vs " + nB + "; " + MIN_REPETITIONS + " a side needed)";
            };
        }

        /** Why a significant test did not separate: the ratio's interval includes 1, or lies on the other side of it. */
        private String reason() {
            if (!(p < Stats.ALPHA)) {
                return "";
            }
            return ratio.excludesOne() ? "; the test and the ratio of means point opposite ways" : "; the ratio's 95% interval includes 1";
        }

        /** {@code p = 0.003}, {@code p < 0.001}. */
        public String pText() {
            return p < 0.001 ? "p < 0.001" : String.format(Locale.ROOT, "p = %.3f", p);
        }
    }

    private Separation() {
    }

    /** Applies the rule to A and B (one value per completed run; empty arrays are too few). */
    public static Result of(double[] a, double[] b) {
        double p = Stats.mannWhitneyP(a, b);
        Stats.RatioCi ratio = Stats.ratioCi(a, b);
        if (a.length < MIN_REPETITIONS || b.length < MIN_REPETITIONS) {
            return new Result(Verdict.TOO_FEW, p, a.length, b.length, ratio);
        }
        if (!(p < Stats.ALPHA) || !ratio.excludesOne()) {
            return new Result(Verdict.NOT_SEPARATED, p, a.length, b.length, ratio);
        }
        // U counts the pairs in which A is above B: under half of them, A tends lower
        double aAbove = Stats.u(a, b) + ties(a, b) / 2.0;
        boolean aLowerByTest = aAbove < (double) a.length * b.length / 2;
        boolean aLowerByMeans = ratio.low() > 1;
        if (aLowerByTest != aLowerByMeans) {
            return new Result(Verdict.NOT_SEPARATED, p, a.length, b.length, ratio); // the test and the means disagree
        }
        return new Result(aLowerByMeans ? Verdict.A_LOWER : Verdict.B_LOWER, p, a.length, b.length, ratio);
    }

    private static long ties(double[] a, double[] b) {
        long t = 0;
        for (double x : a) {
            for (double y : b) {
                if (x == y) {
                    t++;
                }
            }
        }
        return t;
    }
}
