package org.jmclbench.tooling.report;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Graphics2D;
import java.awt.geom.Line2D;
import java.awt.geom.Rectangle2D;
import java.util.HashMap;
import java.util.Map;

import org.jfree.chart.axis.CategoryAxis;
import org.jfree.chart.axis.ValueAxis;
import org.jfree.chart.plot.CategoryPlot;
import org.jfree.chart.plot.PlotOrientation;
import org.jfree.chart.renderer.category.BarRenderer;
import org.jfree.chart.renderer.category.CategoryItemRendererState;
import org.jfree.chart.ui.RectangleEdge;
import org.jfree.data.category.CategoryDataset;

/**
 * Bars with an error bar from each value's own [low, high]: a bootstrap interval is not
 * symmetric about the mean, which JFreeChart's StatisticalBarRenderer (mean ± one value) assumes.
 */
final class ErrorBarRenderer extends BarRenderer {
    private static final long serialVersionUID = 1L;
    private final Map<Long, double[]> intervals = new HashMap<>();

    /** The interval of the bar at (series row, category column); null draws none. */
    void interval(int row, int column, double[] lowHigh) {
        if (lowHigh != null) {
            intervals.put(((long) row << 32) | column, lowHigh);
        }
    }

    @Override
    public void drawItem(Graphics2D g2, CategoryItemRendererState state, Rectangle2D dataArea, CategoryPlot plot,
            CategoryAxis domainAxis, ValueAxis rangeAxis, CategoryDataset dataset, int row, int column, int pass) {
        super.drawItem(g2, state, dataArea, plot, domainAxis, rangeAxis, dataset, row, column, pass);
        double[] e = intervals.get(((long) row << 32) | column);
        if (pass != getPassCount() - 1 || e == null || dataset.getValue(row, column) == null) { // over the bar, once
            return;
        }
        PlotOrientation o = plot.getOrientation();
        double centre = calculateBarW0(plot, o, dataArea, domainAxis, state, row, column) + state.getBarWidth() / 2;
        RectangleEdge edge = plot.getRangeAxisEdge();
        // the axis may start above the low end (a log axis, a floor): cut the bar there, as the page does
        double lower = Math.max(e[0], rangeAxis.getLowerBound());
        double upper = Math.min(e[1], rangeAxis.getUpperBound());
        if (upper < lower) {
            return;
        }
        double lo = rangeAxis.valueToJava2D(lower, dataArea, edge);
        double hi = rangeAxis.valueToJava2D(upper, dataArea, edge);
        double cap = Math.min(8, state.getBarWidth() / 3) / 2;
        g2.setPaint(Color.BLACK);
        g2.setStroke(new BasicStroke(1f));
        if (o == PlotOrientation.VERTICAL) {
            g2.draw(new Line2D.Double(centre, lo, centre, hi));
            g2.draw(new Line2D.Double(centre - cap, lo, centre + cap, lo));
            g2.draw(new Line2D.Double(centre - cap, hi, centre + cap, hi));
        } else {
            g2.draw(new Line2D.Double(lo, centre, hi, centre));
            g2.draw(new Line2D.Double(lo, centre - cap, lo, centre + cap));
            g2.draw(new Line2D.Double(hi, centre - cap, hi, centre + cap));
        }
    }
}
