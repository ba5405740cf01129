package org.jmclbench.tooling.report;

import java.awt.Graphics2D;
import java.awt.geom.Rectangle2D;
import java.util.ArrayList;
import java.util.List;
import java.util.TreeSet;

import org.jfree.chart.axis.AxisState;
import org.jfree.chart.axis.LogAxis;
import org.jfree.chart.axis.LogTick;
import org.jfree.chart.axis.TickType;
import org.jfree.chart.axis.ValueTick;
import org.jfree.chart.ui.RectangleEdge;
import org.jfree.chart.ui.TextAnchor;
import org.jfree.data.Range;

/**
 * A log axis a reader can read values from. JFreeChart labels whole powers of ten only, so an
 * axis that spans a decade or less (response times of 0.6 to 9 ms) had one label, or none. Where
 * the powers of ten give fewer than three labels, 2 and 5 times each power are labelled too; the
 * other minor ticks stay as grid lines. An axis fitted to its data that holds fewer than three of
 * those values (1 to 2.6 bytes) is carried up to its third.
 */
final class ReadableLogAxis extends LogAxis {
    private static final long serialVersionUID = 1L;
    private static final int[] STEPS = {1, 2, 5};
    private final boolean roundUp;

    /** @param roundUp whether a range fitted to the data may be carried up (not a percentile axis, which ends at the data) */
    ReadableLogAxis(String label, boolean roundUp) {
        super(label);
        this.roundUp = roundUp;
    }

    @Override
    protected void autoAdjustRange() {
        super.autoAdjustRange();
        if (!roundUp || !isAutoRange()) {
            return;
        }
        double low = Math.max(getRange().getLowerBound(), getSmallestValue());
        double high = getRange().getUpperBound();
        for (int i = 0; i < 6 && oneTwoFive(low, high).size() < 3; i++) {
            high = nextStep(high);
        }
        if (high > getRange().getUpperBound()) {
            setRange(new Range(getRange().getLowerBound(), high), false, false);
        }
    }

    /** The smallest of 1, 2 and 5 times a power of ten above {@code v}. */
    static double nextStep(double v) {
        int k = (int) Math.floor(Math.log10(v));
        for (int e = k; ; e++) {
            for (int m : STEPS) {
                double c = m * Math.pow(10, e);
                if (c > v * (1 + 1e-9)) {
                    return c;
                }
            }
        }
    }

    /** 1, 2 and 5 times the powers of ten from {@code low} to {@code high}. */
    private static TreeSet<Double> oneTwoFive(double low, double high) {
        TreeSet<Double> out = new TreeSet<>();
        for (int k = (int) Math.floor(Math.log10(low)); k <= (int) Math.ceil(Math.log10(high)); k++) {
            for (int m : STEPS) {
                double v = m * Math.pow(10, k);
                if (v >= low * (1 - 1e-9) && v <= high * (1 + 1e-9)) {
                    out.add(v);
                }
            }
        }
        return out;
    }

    @Override
    @SuppressWarnings({"rawtypes", "unchecked"})
    public List refreshTicks(Graphics2D g2, AxisState state, Rectangle2D dataArea, RectangleEdge edge) {
        List<ValueTick> ticks = super.refreshTicks(g2, state, dataArea, edge);
        if (ticks.stream().filter(t -> t.getTickType() == TickType.MAJOR).count() >= 3) {
            return ticks;
        }
        TreeSet<Double> labelled = oneTwoFive(Math.max(getRange().getLowerBound(), getSmallestValue()),
                getRange().getUpperBound());
        List out = new ArrayList();
        for (ValueTick t : ticks) {
            if (t.getTickType() == TickType.MINOR && !near(labelled, t.getValue())) {
                out.add(t);
            }
        }
        for (double v : labelled) {
            out.add(new LogTick(TickType.MAJOR, v, createTickLabel(v), anchor(edge)));
        }
        return out;
    }

    /** A minor tick where a label now stands (they differ in the last bits). */
    private static boolean near(TreeSet<Double> values, double v) {
        Double below = values.floor(v * (1 + 1e-9));
        return below != null && Math.abs(below - v) <= 1e-9 * v;
    }

    /** Where LogAxis itself anchors a label on this edge. */
    private static TextAnchor anchor(RectangleEdge edge) {
        if (edge == RectangleEdge.TOP) {
            return TextAnchor.BOTTOM_CENTER;
        }
        if (edge == RectangleEdge.BOTTOM) {
            return TextAnchor.TOP_CENTER;
        }
        return edge == RectangleEdge.RIGHT ? TextAnchor.CENTER_LEFT : TextAnchor.CENTER_RIGHT;
    }
}
