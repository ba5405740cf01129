package org.jmclbench.tooling.report;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import org.jmclbench.tooling.Fixtures;
import org.jmclbench.tooling.cli.CodeVersion;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;

/**
 * The report and compare on a store written by the runner itself (matrix with the runner's fake
 * runtimes), so that what the runner writes and what the report reads cannot drift apart.
 */
class ReportOnRunnerStoreTest {

    @TempDir
    Path dir;

    @Test
    void reportAndCompareReadWhatTheMatrixWrote() throws Exception {
        Fixtures.home(dir);
        Fixtures.FakeJvms jvms = Fixtures.FakeJvms.in(dir);
        Path db = dir.resolve("results/results.db");
        Fixtures.CliResult m = Fixtures.cli("matrix", "--datasets", "tiny", "--particles", "100,200", "--policies", "skip",
                "--repeat", "3", "--java", jvms.java17(), "--java", jvms.java21(), "--java", jvms.crashing11(), "--db", db.toString());
        assertEquals(0, m.exitCode(), m.out() + m.err());

        Fixtures.CliResult r = Fixtures.cli("report", "--db", db.toString(), "--out", dir.resolve("report").toString());
        assertEquals(0, r.exitCode(), r.out() + r.err());
        String html = Files.readString(dir.resolve("report/index.html"));
        String code = CodeVersion.current() == null ? "which jmclbench version made them is not recorded: the store predates that"
                : "every run by jmclbench commit " + CodeVersion.current();
        assertTrue(html.contains(" runs (" + code + "), built "), "the page says which code made its runs");
        Matcher data = Pattern.compile("(?s)id=\"jmclbench-data\">(.*?)</script>").matcher(html);
        assertTrue(data.find());
        JsonNode model = new ObjectMapper().readTree(data.group(1));
        assertEquals(3 * 2 * 3, model.get("runCount").asInt());

        List<String> okConfigs = new ArrayList<>();
        int failedCells = 0;
        for (JsonNode c : model.get("cells")) {
            if (c.get("ok").asInt() == 0) {
                failedCells++;
                assertEquals(3, c.get("failures").size(), "each failed run listed with its stderr");
                assertFalse(c.at("/failures/0/stderrTail").asText().isEmpty());
                continue;
            }
            String where = c.get("config").asText() + " " + c.get("particles").asInt();
            assertEquals(3, c.at("/metrics/MISS_COUNT/n").asInt(), where);
            assertEquals(1.0, c.at("/metrics/MISS_COUNT/mean").asDouble(), 1e-9, where);
            assertEquals(0.003, c.at("/metrics/DEVIATION/mean").asDouble(), 1e-9, where);
            assertTrue(c.at("/metrics/LATENCY_MEAN/mean").asDouble() > 0, where);
            // Series and histograms as the runner's ingest stores them, reaching the page through the cell's charts.
            String config = c.get("config").asText();
            int particles = c.get("particles").asInt();
            List<JsonNode> latency = ReportCommandTest.seriesOf(ReportCommandTest.chart(model, "skip", particles, "latency-index"), config);
            assertEquals(9, latency.get(0).get("points").size(), where + ": 10 predict jobs, 1 skipped");
            assertEquals(4, latency.get(1).get("points").size(), where + ": update");
            assertEquals(3, ReportCommandTest.seriesOf(ReportCommandTest.chart(model, "skip", particles, "deviation-time"), config).size(),
                    where + ": one line per repetition");
            JsonNode trajectory = ReportCommandTest.chart(model, "skip", particles, "trajectory");
            assertFalse(ReportCommandTest.seriesOf(trajectory, config).get(0).get("points").isEmpty(), where);
            boolean real = false;
            for (JsonNode series : trajectory.get("series")) {
                real |= series.get("name").asText().equals("real") && !series.get("points").isEmpty();
            }
            assertTrue(real, where + ": the dataset's ground truth");
            assertFalse(ReportCommandTest.seriesOf(ReportCommandTest.chart(model, "skip", particles, "spectrum"), config)
                    .get(0).get("points").isEmpty(), where);
            assertFalse(ReportCommandTest.seriesOf(ReportCommandTest.chart(model, "skip", particles, "jitter-cdf"), config)
                    .get(0).get("points").isEmpty(), where);
            // per-task accounting: predict released 10 and dropped 1 (the summary predates missRatio: from its definition)
            assertEquals(0.1, c.at("/metrics/predict.MISS_RATIO/mean").asDouble(), 1e-9, where);
            assertEquals(0.0, c.at("/metrics/update.MISS_RATIO/mean").asDouble(), 1e-9, where);
            assertEquals(1.0, c.at("/metrics/predict.DROPPED/mean").asDouble(), 1e-9, where);
            // the completion curves from the per-task response-time histograms the ingest stored: 9 of 10, 4 of 4
            for (String[] t : new String[][] {{"predict", "0.9"}, {"update", "1.0"}}) {
                JsonNode pts = ReportCommandTest.seriesOf(ReportCommandTest.chart(model, "skip", particles, "completion-" + t[0]), config)
                        .get(0).get("points");
                assertEquals(Double.parseDouble(t[1]), pts.get(pts.size() - 1).get(1).asDouble(), 1e-9, where + " " + t[0]);
            }
            if (!okConfigs.contains(c.get("config").asText())) {
                okConfigs.add(c.get("config").asText());
            }
        }
        assertEquals(2, okConfigs.size(), okConfigs.toString());
        assertEquals(2, failedCells, "the crashing runtime at both particle counts");
        assertTrue(Files.isRegularFile(dir.resolve("report/charts/tiny-skip-100-spectrum.svg")));

        Fixtures.CliResult cmp = Fixtures.cli("compare", "--db", db.toString(), "--a", okConfigs.get(0), "--b", okConfigs.get(1));
        assertEquals(0, cmp.exitCode(), cmp.out() + cmp.err());
        assertTrue(cmp.out().contains("== tiny  skip  100 particles =="), cmp.out());
        // The fake runtimes measure identical values: ratio 1, every rank tied, no difference.
        String latency = cmp.out().lines().filter(l -> l.startsWith("task latency mean")).findFirst().orElseThrow();
        assertTrue(latency.contains("1.000") && latency.endsWith("not separated: n too small to separate (p = 1.000, n = 3 vs 3; 10 a side needed)"),
                latency);
    }
}
