package org.jmclbench.tooling.report;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.awt.geom.Rectangle2D;
import java.util.List;

import org.jfree.chart.ChartRenderingInfo;
import org.jfree.chart.JFreeChart;
import org.jfree.chart.axis.AxisState;
import org.jfree.chart.axis.LogTick;
import org.jfree.chart.axis.TickType;
import org.jfree.chart.axis.ValueAxis;
import org.jfree.chart.plot.XYPlot;
import org.junit.jupiter.api.Test;

/** An exported log axis labels enough ticks to read a value from, however few decades it spans. */
class ExportedLogAxisTest {

    @Test
    void anAxisWithinOneDecadeLabelsTwoAndFiveTimesItsPowersOfTen() {
        // the evaluation's completion charts: response times of 0.6 to 9 ms had "1" as their only label
        assertEquals(List.of("1", "2", "5"), xLabels(log(ChartSpec.Format.NUMBER, 0.6, 9.0)));
    }

    @Test
    void aPercentileAxisOfTwoDecadesGetsItsHalvesAndFifthsToo() {
        // the abort-latency chart: 0% and 90% only, though its jobs reach the 98th percentile
        assertEquals(List.of("0%", "50%", "80%", "90%", "95%"), xLabels(log(ChartSpec.Format.PERCENTILE, 1.0, 40.0)));
    }

    @Test
    void anAxisOfManyDecadesKeepsItsPowersOfTenAlone() {
        assertEquals(List.of("0.01", "0.1", "1", "10"), xLabels(log(ChartSpec.Format.NUMBER, 0.002, 20.0)));
    }

    @Test
    void aPercentileLabelHasTheDecimalsItNeeds() {
        assertEquals(List.of("0%", "50%", "90%", "95%", "98%", "99%", "99.5%", "99.8%", "99.9%", "99.95%"),
                java.util.stream.DoubleStream.of(1, 2, 10, 20, 50, 100, 200, 500, 1000, 2000).mapToObj(ChartFormats::percentile)
                        .toList());
    }

    @Test
    void anAxisFittedToLessThanThreeLabelsIsCarriedUpToItsThird() {
        // the page's bytes-per-release chart: one bar of 2.6 B, labels 1 B and 2 B
        assertEquals(List.of("1", "2", "5"), xLabels(new ChartSpec.Axis("x", ChartSpec.Scale.LOG, ChartSpec.Format.NUMBER, null,
                null), 1.0, 2.6));
        assertEquals(List.of("5", "10", "20"), xLabels(new ChartSpec.Axis("x", ChartSpec.Scale.LOG, ChartSpec.Format.NUMBER, null,
                null), 3.0, 4.0));
        // a percentile axis ends where its data end (its last point is p = 1 - 1/n): not carried up
        assertEquals(List.of("0%"), xLabels(new ChartSpec.Axis("x", ChartSpec.Scale.LOG, ChartSpec.Format.PERCENTILE, 1.0,
                null), 1.0, 1.8));
    }

    private static ChartSpec.Axis log(ChartSpec.Format format, double min, double max) {
        return new ChartSpec.Axis("x", ChartSpec.Scale.LOG, format, min, max);
    }

    /** The labelled ticks of a line chart's x axis, as exported. */
    private static List<String> xLabels(ChartSpec.Axis x) {
        return xLabels(x, x.min(), x.max());
    }

    /** The same, for a line from {@code from} to {@code to}. */
    private static List<String> xLabels(ChartSpec.Axis x, double from, double to) {
        ChartSpec.Series s = new ChartSpec.Series("a", "c", "javase", "#1f77b4", ChartSpec.Style.line(1),
                List.of(new double[] {from, 1}, new double[] {to, 2}), null, null, null, null);
        ChartSpec spec = new ChartSpec("c", "c", new ChartSpec.Setting("d", "skip", null), "t", ChartSpec.Kind.LINES, false,
                x, ChartSpec.Axis.linear("y"), null, List.of(s), List.of(), null, false);
        JFreeChart chart = ChartExporter.render(spec);
        ChartRenderingInfo info = new ChartRenderingInfo();
        java.awt.image.BufferedImage img = chart.createBufferedImage(900, 520, info);
        Rectangle2D area = info.getPlotInfo().getDataArea();
        XYPlot plot = chart.getXYPlot();
        ValueAxis axis = plot.getDomainAxis();
        List<?> ticks = axis.refreshTicks(img.createGraphics(), new AxisState(), area, plot.getDomainAxisEdge());
        return ticks.stream().map(LogTick.class::cast).filter(t -> t.getTickType() == TickType.MAJOR)
                .map(t -> t.getAttributedLabel() == null ? "" : text(t)).toList();
    }

    private static String text(LogTick t) {
        java.text.AttributedCharacterIterator it = t.getAttributedLabel().getIterator();
        StringBuilder b = new StringBuilder();
        for (char c = it.first(); c != java.text.CharacterIterator.DONE; c = it.next()) {
            b.append(c);
        }
        return b.toString();
    }
}
