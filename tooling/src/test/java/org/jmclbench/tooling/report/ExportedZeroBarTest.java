package org.jmclbench.tooling.report;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * A bar of value 0 is marked "0" at the axis, on a linear axis as on a log one: the evaluation's
 * missCount figure drew nothing for a runtime with no dropped job (400 particles) and nothing for
 * one not run at that count (25600), two different things that looked the same.
 */
class ExportedZeroBarTest {

    @Test
    void aZeroBarIsMarkedAndAMissingOneIsNot(@TempDir Path dir) throws Exception {
        assertEquals(1, zeroMarks(dir, "zero", 0.0) - zeroMarks(dir, "missing", null), "one mark more for the bar of 0");
    }

    /** The "0"s written in the SVG of a chart of two bars, {@code first} and 2, on a linear axis from 0 to 3. */
    private static long zeroMarks(Path dir, String stem, Double first) throws Exception {
        List<Double> values = new ArrayList<>(Arrays.asList(first, 2.0));
        ChartSpec.Series s = new ChartSpec.Series("native", "native", "native", "#1f77b4", ChartSpec.Style.BAR, null, values, null,
                null, null);
        ChartSpec spec = new ChartSpec("misses", stem, new ChartSpec.Setting("d", "skip", null), "t", ChartSpec.Kind.BARS, false,
                ChartSpec.Axis.linear("particles"), ChartSpec.Axis.linear("dropped jobs per run").range(0.0, 3.0),
                List.of(new ChartSpec.Category("400", null, null), new ChartSpec.Category("1600", null, null)), List.of(s), List.of(),
                null, false);
        new ChartExporter(dir).write(spec);
        String svg = Files.readString(dir.resolve(stem + ".svg"));
        return svg.split(">0</text>", -1).length - 1;
    }
}
