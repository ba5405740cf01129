package org.jmclbench.tooling.report;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Font;
import java.awt.Graphics2D;
import java.awt.geom.Rectangle2D;
import java.util.ArrayList;
import java.util.List;

import org.jfree.chart.axis.AxisState;
import org.jfree.chart.axis.NumberAxis;
import org.jfree.chart.axis.NumberTick;
import org.jfree.chart.axis.TickType;
import org.jfree.chart.axis.ValueTick;
import org.jfree.chart.plot.IntervalMarker;
import org.jfree.chart.plot.ValueMarker;
import org.jfree.chart.plot.XYPlot;
import org.jfree.chart.ui.Layer;
import org.jfree.chart.ui.RectangleAnchor;
import org.jfree.chart.ui.RectangleEdge;
import org.jfree.chart.ui.TextAnchor;

/**
 * The exported file's vertical axis with a band for +infinity on top ({@link ChartSpec.Beyond}),
 * as the page draws it: numbers up to the band's start, then a dashed break, a grey band named
 * for what it holds, and one tick in it reading {@code ∞} where the marks sit.
 */
final class BeyondAxis extends NumberAxis {

    private static final long serialVersionUID = 1L;
    /** The band's shade and its break's colour: light enough not to hide the marks. */
    static final Color SHADE = new Color(0xee, 0xee, 0xee);
    static final Color BREAK = new Color(0x88, 0x88, 0x88);

    private final ChartSpec.Beyond band;

    private BeyondAxis(String label, ChartSpec.Beyond band) {
        super(label);
        this.band = band;
    }

    /** A linear axis from {@code a}'s min to its max (the band's top), its ticks cut at the band. */
    static BeyondAxis of(ChartSpec.Axis a) {
        BeyondAxis axis = new BeyondAxis(a.label(), a.beyond());
        axis.setAutoRangeIncludesZero(false);
        axis.setRange(a.min() == null ? 0 : a.min(), a.max());
        return axis;
    }

    /** The band behind the data and its break, with the band's name at its top left. */
    static void shade(XYPlot plot, ChartSpec.Beyond band, double top) {
        IntervalMarker shade = new IntervalMarker(band.from(), top, SHADE);
        shade.setLabel(band.label());
        shade.setLabelFont(new Font(Font.SANS_SERIF, Font.PLAIN, 11));
        shade.setLabelPaint(Color.DARK_GRAY);
        shade.setLabelAnchor(RectangleAnchor.TOP_LEFT);
        shade.setLabelTextAnchor(TextAnchor.TOP_LEFT);
        plot.addRangeMarker(shade, Layer.BACKGROUND);
        plot.addRangeMarker(new ValueMarker(band.from(), BREAK,
                new BasicStroke(1.2f, BasicStroke.CAP_BUTT, BasicStroke.JOIN_MITER, 10f, new float[] {6f, 4f}, 0f)), Layer.BACKGROUND);
    }

    @Override
    public List<ValueTick> refreshTicks(Graphics2D g2, AxisState state, Rectangle2D dataArea, RectangleEdge edge) {
        List<ValueTick> ticks = new ArrayList<>();
        for (Object t : super.refreshTicks(g2, state, dataArea, edge)) {
            if (t instanceof ValueTick v && v.getValue() <= band.from() * (1 + 1e-9)) { // a tick at the break, computed a little above it, is the last number
                ticks.add(v); // no number inside the band: nothing there is one
            }
        }
        boolean left = edge == RectangleEdge.LEFT;
        ticks.add(new NumberTick(TickType.MAJOR, band.at(), band.tick(), left ? TextAnchor.CENTER_RIGHT : TextAnchor.CENTER_LEFT,
                TextAnchor.CENTER, 0));
        return ticks;
    }
}
