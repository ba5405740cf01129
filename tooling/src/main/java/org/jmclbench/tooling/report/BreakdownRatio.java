package org.jmclbench.tooling.report;

import java.util.Locale;

/**
 * A configuration's breakdown load over the C baseline's, as far as two brackets know them. Each
 * breakdown load lies in [holds, fails): the count that held and the one above it that did not
 * (no {@code fails}: it held at every count tried). The ratio then lies between holds / C's fails
 * and fails / C's holds; the ratio of the two held counts alone read sharper than the brackets
 * are (two 10% brackets leave it anywhere in 0.91-1.10).
 */
public final class BreakdownRatio {

    private BreakdownRatio() {
    }

    /**
     * {@code 0.65-0.77x}; {@code >= 1.10x} or {@code <= 0.91x} where one of the two held at every
     * count tried; {@code ?} where both did; {@code 1.00x} for the baseline itself; empty where either
     * held at no count.
     */
    public static String of(Integer holds, Integer fails, Integer cHolds, Integer cFails, boolean isBaseline) {
        if (holds == null || cHolds == null) {
            return "";
        }
        if (isBaseline) {
            return "1.00x";
        }
        if (fails == null && cFails == null) {
            return "? (both held at every count)";
        }
        if (fails == null) {
            return ">= " + x((double) holds / cFails) + "x";
        }
        if (cFails == null) {
            return "<= " + x((double) fails / cHolds) + "x";
        }
        return x((double) holds / cFails) + "-" + x((double) fails / cHolds) + "x";
    }

    private static String x(double v) {
        return String.format(Locale.ROOT, "%.2f", v);
    }
}
