package org.jmclbench.tooling.report;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.geom.Rectangle2D;
import java.awt.image.BufferedImage;
import java.util.List;

import org.jfree.chart.ChartRenderingInfo;
import org.jfree.chart.JFreeChart;
import org.jfree.chart.plot.CategoryPlot;
import org.junit.jupiter.api.Test;

/** The exported bar charts draw each bar's own [low, high], not the mean plus or minus one value. */
class ExportedErrorBarTest {

    @Test
    void theErrorBarSpansTheBootstrapIntervalNotASymmetricOne() {
        // mean 2, interval [1.5, 5]: a symmetric bar would end at 2.5 below or at -1 above
        ChartSpec.Series s = new ChartSpec.Series("misses", "c", "javase", "#aaddff", ChartSpec.Style.BAR, null,
                List.of(2.0), List.of(new double[] {1.5, 5.0}), null, null);
        ChartSpec spec = new ChartSpec("misses", "misses", new ChartSpec.Setting("d", "skip", null), "t", ChartSpec.Kind.BARS,
                false, ChartSpec.Axis.linear("particles"), ChartSpec.Axis.linear("misses").range(0.0, 6.0),
                List.of(new ChartSpec.Category("100", null, null)), List.of(s), List.of(), null, false);
        JFreeChart chart = ChartExporter.render(spec);
        ChartRenderingInfo info = new ChartRenderingInfo();
        BufferedImage img = chart.createBufferedImage(900, 520, info);
        Rectangle2D area = info.getPlotInfo().getDataArea();
        CategoryPlot plot = chart.getCategoryPlot();
        int cx = (int) Math.round(area.getCenterX());
        assertTrue(dark(img, cx, y(plot, area, 4.5)), "the bar reaches up to 5");
        assertFalse(dark(img, cx, y(plot, area, 5.5)), "and not beyond");
        assertTrue(dark(img, cx, y(plot, area, 1.75)), "down to 1.5");
        assertFalse(dark(img, cx, y(plot, area, 1.2)), "and not below");
    }

    private static int y(CategoryPlot plot, Rectangle2D area, double value) {
        return (int) Math.round(plot.getRangeAxis().valueToJava2D(value, area, plot.getRangeAxisEdge()));
    }

    /** A dark pixel within two pixels of x (the black line is one pixel wide, antialiased). */
    private static boolean dark(BufferedImage img, int x, int y) {
        for (int dx = -2; dx <= 2; dx++) {
            int rgb = img.getRGB(x + dx, y);
            if (((rgb >> 16) & 0xff) < 140) { // darker than the bar (red 0xaa), the grid and the background
                return true;
            }
        }
        return false;
    }
}
