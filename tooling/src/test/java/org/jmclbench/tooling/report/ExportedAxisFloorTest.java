package org.jmclbench.tooling.report;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.List;

import org.jfree.chart.JFreeChart;
import org.junit.jupiter.api.Test;

/**
 * A linear axis whose spec starts at 0 starts there in the exported file, as on the page (Chart.js
 * takes the spec's min as the axis' start): the evaluation's response-time p99 figures started at
 * 0.2 ms, where the page starts at 0, so heights did not compare between the two.
 */
class ExportedAxisFloorTest {

    @Test
    void aLineChartFromZeroStartsAtZero() {
        ChartSpec.Series s = new ChartSpec.Series("native", "native", "native", "#1f77b4", ChartSpec.Style.line(1.5),
                List.of(new double[] {400, 0.28}, new double[] {1600, 0.34}, new double[] {6400, 1.6}), null, null, null, null);
        ChartSpec spec = new ChartSpec("response-p99-predict", "p99", new ChartSpec.Setting("d", "skip", null), "t",
                ChartSpec.Kind.LINES, false, new ChartSpec.Axis("particles (log)", ChartSpec.Scale.LOG, ChartSpec.Format.NUMBER, null,
                null), ChartSpec.Axis.linear("response time p99 (ms)").range(0.0, null), null, List.of(s), List.of(), null, false);
        JFreeChart chart = ChartExporter.render(spec);
        assertEquals(0.0, chart.getXYPlot().getRangeAxis().getLowerBound(), 1e-12);
    }
}
