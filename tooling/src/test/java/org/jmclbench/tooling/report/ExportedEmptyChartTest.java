package org.jmclbench.tooling.report;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** An exported chart with nothing to draw (every run at its setting failed) says so, as the page does. */
class ExportedEmptyChartTest {

    @Test
    void barsAndLinesWithNoSeriesSayWhyTheyAreEmpty(@TempDir Path dir) throws Exception {
        ChartSpec.Setting at = new ChartSpec.Setting("d", "skip", 400);
        ChartSpec bars = new ChartSpec("misses", "empty-bars", at, "t", ChartSpec.Kind.BARS, false,
                ChartSpec.Axis.linear("particles"), ChartSpec.Axis.linear("dropped jobs per run"),
                List.of(new ChartSpec.Category("400", null, null)), List.of(), List.of(), null, false);
        ChartSpec lines = new ChartSpec("spectrum", "empty-lines", at, "t", ChartSpec.Kind.LINES, false,
                ChartSpec.Axis.linear("x"), ChartSpec.Axis.linear("y"), null, List.of(), List.of(), null, false);
        ChartExporter exporter = new ChartExporter(dir);
        for (ChartSpec spec : List.of(bars, lines)) {
            exporter.write(spec);
            String svg = Files.readString(dir.resolve(spec.stem() + ".svg"));
            // bare axes read as a chart of zeros
            assertTrue(svg.contains("nothing to draw: no completed run has these values"), spec.stem());
        }
    }
}
