package org.jmclbench.tooling.report;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.Graphics2D;
import java.awt.geom.Rectangle2D;
import java.awt.image.BufferedImage;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import org.jfree.chart.JFreeChart;
import org.jfree.chart.axis.AxisState;
import org.jfree.chart.axis.ValueAxis;
import org.jfree.chart.axis.ValueTick;
import org.jfree.chart.ui.RectangleEdge;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * +infinity in an exported file reads as "never completed", not as a number: its marks sat at
 * 1.08 times the highest value on a plain linear axis, which a reader took for 2.25 ms in the
 * evaluation's Figure 4f. The axis' numbers now end below a named band whose one tick reads ∞.
 */
class ExportedInfinityBandTest {

    @TempDir
    Path dir;

    private static ChartSpec spec() {
        ChartSpec.Series finite = new ChartSpec.Series("native", "native", "native", "#1f77b4", ChartSpec.Style.line(1.5),
                List.of(new double[] {400, 0.28}, new double[] {1600, 1.6}), null, null, null, null);
        ChartSpec.Beyond band = new ChartSpec.Beyond(1.7, 1.9, ChartSpec.Beyond.TICK, ChartSpec.Beyond.NEVER_COMPLETED);
        ChartSpec.Series inf = new ChartSpec.Series("javase \u221e", "javase", "javase", "#ff7f0e",
                ChartSpec.Style.marks("triangle", 5, "none"), List.<double[]>of(new double[] {6400, 1.9}), null, null, null, null);
        return new ChartSpec("response-p99-predict", "p99", new ChartSpec.Setting("d", "skip", null), "t", ChartSpec.Kind.LINES, false,
                new ChartSpec.Axis("particles (log)", ChartSpec.Scale.LOG, ChartSpec.Format.NUMBER, null, null),
                ChartSpec.Axis.linear("response time p99 (ms)").range(0.0, null).beyond(band, 2.1), null, List.of(finite, inf),
                List.of(), null, false);
    }

    @Test
    void theAxisNumbersEndBelowTheBandWhoseOnlyTickReadsInfinity() {
        JFreeChart chart = ChartExporter.render(spec());
        ValueAxis y = chart.getXYPlot().getRangeAxis();
        assertEquals(0.0, y.getLowerBound(), 1e-12);
        assertEquals(2.1, y.getUpperBound(), 1e-12, "the band's top is the axis' top");
        Graphics2D g = new BufferedImage(10, 10, BufferedImage.TYPE_INT_RGB).createGraphics();
        @SuppressWarnings("unchecked")
        List<ValueTick> ticks = y.refreshTicks(g, new AxisState(), new Rectangle2D.Double(0, 0, 800, 400), RectangleEdge.LEFT);
        g.dispose();
        for (ValueTick t : ticks) {
            if (t.getValue() > 1.7 * (1 + 1e-9)) {
                assertEquals(1.9, t.getValue(), 1e-12, "no number inside the band");
                assertEquals("\u221e", t.getText());
            }
        }
        assertEquals(1, ticks.stream().filter(t -> "\u221e".equals(t.getText())).count());
        assertTrue(ticks.stream().anyMatch(t -> t.getValue() == 1.5), "numbers below the band as before: " + ticks);
    }

    @Test
    void aRuntimeWithOnlyInfinityMarksIsNamedInTheLegendByItsName() {
        // javase has no number at any count: its marks are its only series, and its entry reads "javase", not "javase \u221e"
        org.jfree.chart.LegendItemCollection items = ChartExporter.render(spec().withLegendPerRuntime()).getXYPlot().getLegendItems();
        List<String> labels = new java.util.ArrayList<>();
        for (int i = 0; i < items.getItemCount(); i++) {
            labels.add(items.get(i).getLabel());
        }
        assertEquals(List.of("native", "javase"), labels);
    }

    @Test
    void theSvgNamesTheBand() throws Exception {
        new ChartExporter(dir).write(spec());
        String svg = Files.readString(dir.resolve("p99.svg"));
        assertTrue(svg.contains("never completed"), "the band is named in the file");
        assertTrue(svg.contains(">\u221e<"), "its tick reads infinity");
    }
}
