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

/**
 * A log axis a reader can read values from. JFreeChart labels whole powers of ten only, so an
 * axis that spans a decade or less (response times of 0.6 to 9 ms) had one label, or none. Where
 * the powers of ten give fewer than three labels, 2 and 5 times each power are labelled too; the
 * other minor ticks stay as grid lines.
 */
final class ReadableLogAxis extends LogAxis {
    private static final long serialVersionUID = 1L;
    private static final int[] STEPS = {1, 2, 5};

    ReadableLogAxis(String label) {
        super(label);
    }

    @Override
    @SuppressWarnings({"rawtypes", "unchecked"})
    public List refreshTicks(Graphics2D g2, AxisState state, Rectangle2D dataArea, RectangleEdge edge) {
        List<ValueTick> ticks = super.refreshTicks(g2, state, dataArea, edge);
        if (ticks.stream().filter(t -> t.getTickType() == TickType.MAJOR).count() >= 3) {
            return ticks;
        }
        double low = Math.max(getRange().getLowerBound(), getSmallestValue());
        double high = getRange().getUpperBound();
        TreeSet<Double> labelled = new TreeSet<>();
        for (int k = (int) Math.floor(Math.log10(low)); k <= (int) Math.ceil(Math.log10(high)); k++) {
            for (int m : STEPS) {
                double v = m * Math.pow(10, k);
                if (v >= low && v <= high) {
                    labelled.add(v);
                }
            }
        }
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
