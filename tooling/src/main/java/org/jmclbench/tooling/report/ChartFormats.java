package org.jmclbench.tooling.report;

import java.math.BigDecimal;
import java.math.MathContext;
import java.text.FieldPosition;
import java.text.NumberFormat;
import java.text.ParsePosition;
import java.util.Locale;

/** How chart values are written where Java writes them: axis ticks of the exported files, tooltips, the evaluation's tables. */
final class ChartFormats {

    private static final String[] BYTE_UNITS = {"B", "kB", "MB", "GB"};

    private ChartFormats() {
    }

    /** Bytes in decimal units (kB = 1000 B, as a log axis' powers of ten read best), three significant digits: 72 B, 2.9 MB. */
    static String bytes(Number b) {
        if (b == null) {
            return "?";
        }
        double v = b.doubleValue();
        int i = 0;
        while (Math.abs(v) >= 1000 && i < BYTE_UNITS.length - 1) {
            v /= 1000;
            i++;
        }
        return new BigDecimal(v).round(new MathContext(3)).stripTrailingZeros().toPlainString() + " " + BYTE_UNITS[i];
    }

    /** 1/(1-p) written as the percentile p: 10 -> 90%, 200 -> 99.5%, 1000 -> 99.9%. */
    static String percentile(double v) {
        double p = 100 - 100 / v;
        // as many decimals as 1/v needs: 200 is 99.5%, never rounded up to 100%
        int decimals = Math.max(0, (int) Math.ceil(Math.log10(v) - 1e-9) - 2);
        return String.format(Locale.ROOT, "%." + decimals + "f%%", Math.max(0, p));
    }

    /** A JFreeChart tick format from one of the functions above. */
    static NumberFormat of(java.util.function.DoubleFunction<String> f) {
        return new NumberFormat() {
            private static final long serialVersionUID = 1L;

            @Override
            public StringBuffer format(double v, StringBuffer to, FieldPosition pos) {
                return to.append(f.apply(v));
            }

            @Override
            public StringBuffer format(long v, StringBuffer to, FieldPosition pos) {
                return format((double) v, to, pos);
            }

            @Override
            public Number parse(String source, ParsePosition pos) {
                throw new UnsupportedOperationException();
            }
        };
    }
}
