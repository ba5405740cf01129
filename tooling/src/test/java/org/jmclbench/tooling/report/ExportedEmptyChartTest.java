package org.jmclbench.tooling.report;

import static org.junit.jupiter.api.Assertions.assertFalse;
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

    @Test
    void aPlaygroundWithItsBeaconsAloneSaysItHasNothingToDraw(@TempDir Path dir) throws Exception {
        // the evaluation store keeps no trajectories: its trajectory charts were the beacons on an empty playground
        ChartSpec.Setting at = new ChartSpec.Setting("d", "skip", 400);
        ChartSpec.Series beacons = new ChartSpec.Series("beacons", null, null, "#000000", ChartSpec.Style.marks("triangle", 9, "#ffd400"),
                List.of(new double[] {0, 1}, new double[] {3, 0}, new double[] {3, 2}), null, null, null, null);
        ChartSpec trajectory = new ChartSpec("trajectory", "beacons-alone", at, "t", ChartSpec.Kind.LINES, false,
                ChartSpec.Axis.linear("x (m)"), ChartSpec.Axis.linear("y (m)"), null, List.of(beacons), List.of(), null, false);
        new ChartExporter(dir).write(trajectory);
        assertTrue(Files.readString(dir.resolve("beacons-alone.svg")).contains("nothing to draw: no completed run has these values"));
        ChartSpec.Series estimate = new ChartSpec.Series("native estimate", "native", "native", "#1f77b4", ChartSpec.Style.line(1.2),
                List.of(new double[] {0, 0}, new double[] {1, 1}), null, null, null, null);
        ChartSpec drawn = new ChartSpec("trajectory", "with-estimate", at, "t", ChartSpec.Kind.LINES, false,
                ChartSpec.Axis.linear("x (m)"), ChartSpec.Axis.linear("y (m)"), null, List.of(beacons, estimate), List.of(), null, false);
        new ChartExporter(dir).write(drawn);
        assertFalse(Files.readString(dir.resolve("with-estimate.svg")).contains("nothing to draw"));
    }

    @Test
    void aChartOfNoSettingWhoseMarksNameNoRuntimeIsNoEmptyChart(@TempDir Path dir) throws Exception {
        // the evaluation's tests in two evaluations (Figure 14): marks of pairs of configurations, coloured by outcome
        ChartSpec.Series held = new ChartSpec.Series("separated the same way in both", null, null, "#2ca02c",
                ChartSpec.Style.marks("circle", 4, null), List.of(new double[] {0.5, 0.6}, new double[] {2, 2.1}), null, null, null, null);
        ChartSpec tests = new ChartSpec("reproducibility", "tests", null, "t", ChartSpec.Kind.LINES, false,
                ChartSpec.Axis.linear("before"), ChartSpec.Axis.linear("now"), null, List.of(held), List.of(), null, false);
        new ChartExporter(dir).write(tests);
        assertFalse(Files.readString(dir.resolve("tests.svg")).contains("nothing to draw"));
    }
}
