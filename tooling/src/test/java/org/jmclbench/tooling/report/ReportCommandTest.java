package org.jmclbench.tooling.report;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import org.jmclbench.tooling.Fixtures;
import org.jmclbench.tooling.cli.JmclbenchCli;
import org.jmclbench.tooling.store.StoredRun;
import org.jmclbench.tooling.store.StoredRuns;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;

/** The report folder built from a fixture store: self-contained page, escaped strings, exports, aggregates. */
class ReportCommandTest {

    @TempDir
    static Path dir;
    static Path db;
    static Path out;
    static String html;

    @BeforeAll
    static void build() throws Exception {
        db = ReportFixtures.write(ReportFixtures.mixed(), dir, "results.db");
        out = dir.resolve("report");
        assertEquals(0, JmclbenchCli.execute("report", "--db", db.toString(), "--out", out.toString()));
        html = Files.readString(out.resolve("index.html"));
    }

    @Test
    void pageIsSelfContained() {
        // No element loads anything: no src/href to a URL, no stylesheet link, no import.
        Matcher m = Pattern.compile("(?i)<(script|link|img|iframe)[^>]*(src|href)\\s*=").matcher(html);
        assertFalse(m.find(), "an element that loads a resource: " + (m.find(0) ? m.group() : ""));
        assertTrue(html.contains("default-src 'none'"), "a content security policy that forbids every request");
        assertTrue(html.contains("Chart.js v4"), "Chart.js inlined from the WebJar");
        assertFalse(html.contains("sourceMappingURL"), "no source map reference");
    }

    @Test
    void hostileStringsNeverReachTheHtmlUnescaped() {
        assertFalse(html.contains(ReportFixtures.XSS_RUNTIME), "the runtime name appears raw");
        assertFalse(html.contains("<img src=x"), "a version string appears raw");
        assertFalse(html.contains("<b>bold</b>"), "a failure message appears raw");
        // There are exactly five script elements: the data, Chart.js, the page's plugins, its chart configuration and its own.
        assertEquals(5, Pattern.compile("<script").matcher(html).results().count());
    }

    @Test
    void inlinedDataHasTheAggregatesOfTheStore() throws Exception {
        Matcher m = Pattern.compile("(?s)<script type=\"application/json\" id=\"jmclbench-data\">(.*?)</script>").matcher(html);
        assertTrue(m.find());
        JsonNode data = new ObjectMapper().readTree(m.group(1));
        assertEquals(6 * 2 * 3 * 3, data.get("runCount").asInt());
        assertEquals("skip", data.at("/defaults/policy").asText());
        for (JsonNode cfg : data.get("configs")) {
            if (cfg.get("id").asText().equals("native")) {
                assertEquals("[\"run\",\"-n\",\"1\",\"--seed\",\"1\"]", cfg.get("flags").toString(), "arguments keep their repeats");
                assertTrue(cfg.get("nativeBaseline").asBoolean());
            }
        }
        assertEquals(400, data.at("/defaults/particles").asInt());
        JsonNode xss = null;
        JsonNode unsupported = null;
        for (JsonNode c : data.get("cells")) {
            if (c.get("policy").asText().equals("skip") && c.get("particles").asInt() == 400) {
                if (c.get("config").asText().equals(ReportFixtures.XSS_RUNTIME + "/g1")) {
                    xss = c;
                }
                if (c.get("config").asText().equals("temurin-11/shenandoah")) {
                    unsupported = c;
                }
            }
        }
        assertNotNull(xss, "the hostile name survives as data");
        assertEquals(3, xss.at("/metrics/MISS_COUNT/n").asInt());
        // the cell's series reach the page through its charts
        assertFalse(seriesOf(chart(data, "skip", 400, "spectrum"), xss.get("config").asText()).get(0).get("points").isEmpty());
        assertEquals(3, seriesOf(chart(data, "skip", 400, "deviation-time"), xss.get("config").asText()).size());
        assertNotNull(unsupported);
        assertEquals(3, unsupported.get("unsupported").asInt());
        assertTrue(unsupported.at("/metrics/MISS_COUNT/mean").isNull());

        // The mean missCount of a cell is the mean of the runs' summary.json missCount.
        try (StoredRuns store = StoredRuns.open(db, "--db")) {
            List<StoredRun> runs = store.runs().stream()
                    .filter(r -> r.config().equals("temurin-17/g1") && r.policy.equals("terminate") && r.particles == 1600).toList();
            assertEquals(3, runs.size());
            ObjectMapper json = new ObjectMapper();
            double sum = 0;
            for (StoredRun r : runs) {
                sum += json.readTree(r.summaryJson).get("missCount").asDouble();
            }
            for (JsonNode c : data.get("cells")) {
                if (c.get("config").asText().equals("temurin-17/g1") && c.get("policy").asText().equals("terminate")
                        && c.get("particles").asInt() == 1600) {
                    assertEquals(sum / 3, c.at("/metrics/MISS_COUNT/mean").asDouble(), 1e-9);
                }
            }
        }
    }

    @Test
    void aWindowsMissRatioIsEachRunsMissedOverReleasedSoThatWindowsOfOtherLengthsCompare() throws Exception {
        Matcher m = Pattern.compile("(?s)<script type=\"application/json\" id=\"jmclbench-data\">(.*?)</script>").matcher(html);
        assertTrue(m.find());
        JsonNode data = new ObjectMapper().readTree(m.group(1));
        try (StoredRuns store = StoredRuns.open(db, "--db")) {
            List<StoredRun> runs = store.runs().stream()
                    .filter(r -> r.config().equals("temurin-17/g1") && r.policy.equals("skip") && r.particles == 1600).toList();
            assertEquals(3, runs.size());
            for (String window : List.of("warm", "steady")) {
                double sum = 0;
                for (StoredRun r : runs) {
                    sum += r.metric("all/missedOrLate." + window + "/value") / r.metric("all/released." + window + "/value");
                }
                assertTrue(sum > 0, "the fixture misses jobs in both windows");
                JsonNode cell = cellOf(data, "temurin-17/g1", "skip", 1600);
                String key = window.equals("warm") ? "WARM_MISS_RATIO" : "STEADY_MISS_RATIO";
                assertEquals(sum / 3, cell.at("/metrics/" + key + "/mean").asDouble(), 1e-12, key);
                assertEquals(3, cell.at("/metrics/" + key + "/n").asInt(), key);
            }
        }
    }

    private static JsonNode cellOf(JsonNode data, String config, String policy, int particles) {
        for (JsonNode c : data.get("cells")) {
            if (c.get("config").asText().equals(config) && c.get("policy").asText().equals(policy) && c.get("particles").asInt() == particles) {
                return c;
            }
        }
        throw new AssertionError("no cell " + config + " " + policy + " " + particles);
    }

    /** The page's chart of one figure at one setting. */
    static JsonNode chart(JsonNode data, String policy, Integer particles, String id) {
        for (JsonNode c : data.get("charts")) {
            if (c.get("id").asText().equals(id) && c.at("/setting/policy").asText().equals(policy)
                    && (particles == null ? c.at("/setting/particles").isMissingNode() : c.at("/setting/particles").asInt() == particles)) {
                return c;
            }
        }
        throw new AssertionError("no chart " + id + " at " + policy + " " + particles);
    }

    static List<JsonNode> seriesOf(JsonNode chart, String config) {
        List<JsonNode> out = new java.util.ArrayList<>();
        chart.get("series").forEach(s -> {
            if (config.equals(s.path("config").asText(null))) {
                out.add(s);
            }
        });
        return out;
    }

    @Test
    void everyChartIsExportedAsSvgAndPng() throws Exception {
        Path charts = out.resolve("charts");
        for (String policy : List.of("skip", "terminate")) {
            for (String kind : List.of("misses", "deviation", "latency-jitter")) {
                assertChart(charts, "match-short-" + policy + "-" + kind);
            }
            for (int p : List.of(100, 400, 1600)) {
                for (String kind : List.of("causes", "latency-index", "deviation-time", "trajectory", "spectrum", "jitter-cdf")) {
                    assertChart(charts, "match-short-" + policy + "-" + p + "-" + kind);
                }
            }
        }
        String svg = Files.readString(charts.resolve("match-short-skip-misses.svg"));
        assertTrue(svg.contains("Dropped jobs vs particles"), "title in the SVG: what skip's missCount counts");
        assertTrue(Files.readString(charts.resolve("match-short-terminate-misses.svg")).contains("Dropped or aborted jobs vs particles"));
        assertTrue(svg.contains("&lt;script&gt;alert(1)&lt;/script&gt;/g1"), "legend escaped in the SVG");
        assertFalse(svg.contains(ReportFixtures.XSS_RUNTIME));
        String causes = Files.readString(charts.resolve("match-short-skip-400-causes.svg"));
        // a cause drawn (compute, every fixture run's largest); safepoint, never a primary cause at this setting, has no entry
        assertTrue(causes.contains("Why deadlines were missed") && causes.contains(">compute<"), "title and the cause legend in the SVG");
        assertFalse(causes.contains(">safepoint<"), "a cause that was no job's primary one in the legend");
    }

    private static void assertChart(Path charts, String stem) throws Exception {
        Path svg = charts.resolve(stem + ".svg");
        Path png = charts.resolve(stem + ".png");
        assertTrue(Files.isRegularFile(svg), "missing " + svg);
        assertTrue(Files.isRegularFile(png), "missing " + png);
        assertTrue(Files.readString(svg).contains("<svg xmlns="), stem);
        byte[] head = Files.readAllBytes(png);
        assertEquals((byte) 0x89, head[0]);
        assertEquals('P', head[1]);
    }

    @Test
    void placeholdersAreFilledOnceSoInsertedTextIsNeverRescanned() {
        assertEquals("a/*Y*/b1/*Z*/", ReportPage.fill("a/*X*/b/*Y*//*Z*/", java.util.Map.of("X", "/*Y*/", "Y", "1")));
        assertEquals("&lt;script&gt;&amp;&quot;&#39;", ReportPage.escapeHtml("<script>&\"'"));
    }

    @Test
    void runsOfTwoMachinesAreNeverPooled() throws Exception {
        Map<String, Integer> ok = okRuns(edited("merged.db",
                "INSERT INTO machines VALUES ('m-2', 'other-host', '6.8.0', 'AMD EPYC', 4, '[]')",
                "UPDATE runs SET machine_id = 'm-2' WHERE repetition = 3"));
        assertEquals(2, ok.get("native @bench-host"), "repetitions 1 and 2: " + ok);
        assertEquals(1, ok.get("native @other-host"), "repetition 3: " + ok);
        assertFalse(ok.containsKey("native"), "no pooled native: " + ok);
    }

    @Test
    void twoMachinesOfOneHostNameAreNeverPooled() throws Exception {
        Map<String, Integer> ok = okRuns(edited("same-host.db",
                "INSERT INTO machines VALUES ('m-2', 'bench-host', '6.8.0', 'AMD EPYC', 4, '[]')",
                "UPDATE runs SET machine_id = 'm-2' WHERE repetition = 3"));
        assertEquals(1, ok.get("native @bench-host (m-2)"), "the second machine, by host name and id: " + ok);
        assertFalse(ok.containsKey("native @bench-host"), "no native pooled over both machines: " + ok);
    }

    @Test
    void runsAtTwoTimeScalesAreNeverPooled() throws Exception {
        // the third repetition of every configuration made again by a second matrix at --time-scale 0.5 (which, like the
        // fixture's first, tells no workload arguments: a matrix that told them would set its runs apart from the others)
        Map<String, Integer> ok = okRuns(edited("time-scales.db",
                "INSERT INTO matrices VALUES ('x-2', 'm-1', 'jmclbench matrix --time-scale 0.5', 8,"
                        + " '2026-11-22T03:00:00Z', '{\"timeScale\":0.5}')",
                "UPDATE runs SET matrix_id = 'x-2', summary_json = json_set(summary_json, '$.parameters.timeScale', 0.5)"
                        + " WHERE repetition = 3"));
        assertEquals(2, ok.get("native"), "repetitions 1 and 2, at 1: " + ok);
        assertEquals(1, ok.get("native [time scale 0.5]"), "repetition 3, at 0.5: " + ok);
        // the unsupported runs have no summary: the matrix's spec says at which scale they were planned
        assertTrue(ok.containsKey("temurin-11/shenandoah [time scale 0.5]"), ok.toString());
        assertFalse(html.contains(" [time scale "), "a store of one time scale keeps its labels");
    }

    @Test
    void runsOfTwoVersionsOfOneRuntimeAreNeverPooled() throws Exception {
        // temurin-17 updated between two matrices: its third repetitions ran on 17.0.16+8
        Map<String, Integer> ok = okRuns(edited("two-versions.db",
                "UPDATE runs SET runtime_version = '17.0.16+8' WHERE runtime = 'temurin-17' AND repetition = 3"));
        assertEquals(2, ok.get("temurin-17/g1 [17.0.15+6]"), "repetitions 1 and 2, on 17.0.15: " + ok);
        assertEquals(1, ok.get("temurin-17/g1 [17.0.16+8]"), "repetition 3, on 17.0.16: " + ok);
        assertEquals(3, ok.get("native"), "a runtime of one version keeps its name: " + ok);
        assertFalse(html.contains("[17.0.15+6]"), "a store of one version per runtime keeps its labels");
    }

    @Test
    void runsThatDoNotTellTheirVersionAreAGroupOfTheirOwn() throws Exception {
        // temurin-17's third repetitions from a store that kept no version: they were pooled with the runs on
        // 17.0.15+6 as if they had run on it (the audit, grouping by version, then found a cell of 3 runs where it had 2)
        Map<String, Integer> ok = okRuns(edited("unknown-version.db",
                "UPDATE runs SET runtime_version = NULL WHERE runtime = 'temurin-17' AND repetition = 3"));
        assertEquals(2, ok.get("temurin-17/g1 [17.0.15+6]"), "repetitions 1 and 2, on 17.0.15: " + ok);
        assertEquals(1, ok.get("temurin-17/g1 [version unknown]"), "repetition 3, on a version not told: " + ok);
        assertEquals(3, ok.get("native"), "a runtime of one version keeps its name: " + ok);
        // no run tells its version: nothing to tell apart, the names stay
        Map<String, Integer> none = okRuns(edited("no-version.db", "UPDATE runs SET runtime_version = NULL"));
        assertEquals(3, none.get("temurin-17/g1"), none.toString());
    }

    @Test
    void runsThatDoNotTellTheirTimeScaleAreAGroupOfTheirOwn() throws Exception {
        // repetition 3 by a matrix whose spec kept no time scale, nor its summary: not pooled with the runs at 1
        Map<String, Integer> ok = okRuns(edited("unknown-scale.db",
                "INSERT INTO matrices SELECT 'x-2', machine_id, command, order_seed, started_at, json_remove(spec_json, '$.timeScale')"
                        + " FROM matrices LIMIT 1",
                "UPDATE runs SET matrix_id = 'x-2', summary_json = json_remove(summary_json, '$.parameters.timeScale')"
                        + " WHERE repetition = 3"));
        assertEquals(2, ok.get("native"), "repetitions 1 and 2, at 1: " + ok);
        assertEquals(1, ok.get("native [time scale unknown]"), "repetition 3: " + ok);
    }

    @Test
    void runsUnderTwoAllocRatesAreNeverPooled() throws Exception {
        // temurin-17 under --load alloc: repetitions 1 and 2 at the default rates, 3 by a second matrix at 200 MB/s, 64 MB
        Map<String, Integer> ok = okRuns(edited("alloc-rates.db",
                "UPDATE matrices SET spec_json = json_set(spec_json, '$.loadAlloc', '100,16')",
                "INSERT INTO matrices VALUES ('x-2', 'm-1', 'jmclbench matrix --load alloc --load-alloc 200,64', 8,"
                        + " '2026-11-22T03:00:00Z', '{\"timeScale\":1.0,\"loadAlloc\":\"200,64\"}')",
                "UPDATE runs SET load = 'alloc' WHERE runtime = 'temurin-17'",
                "UPDATE runs SET matrix_id = 'x-2' WHERE runtime = 'temurin-17' AND repetition = 3"));
        assertEquals(2, ok.get("temurin-17/g1 [load alloc 100 MB/s, 16 MB live]"), "repetitions 1 and 2: " + ok);
        assertEquals(1, ok.get("temurin-17/g1 [load alloc 200 MB/s, 64 MB live]"), "repetition 3: " + ok);
        assertEquals(3, ok.get("native"), "an idle row keeps its name: " + ok);
    }

    /** A copy of the fixture store, named {@code name}, changed by {@code statements} (another machine, matrix, version). */
    private static Path edited(String name, String... statements) throws Exception {
        Path copy = Files.copy(db, dir.resolve(name));
        try (var c = java.sql.DriverManager.getConnection("jdbc:sqlite:" + copy); var st = c.createStatement()) {
            for (String sql : statements) {
                st.execute(sql);
            }
        }
        return copy;
    }

    /** The ok runs of each skip, 400-particle cell of the report {@code store} gives, by row name. */
    private static Map<String, Integer> okRuns(Path store) throws Exception {
        Path page = dir.resolve(store.getFileName() + "-report");
        assertEquals(0, JmclbenchCli.execute("report", "--db", store.toString(), "--out", page.toString(), "--no-export"));
        Matcher m = Pattern.compile("(?s)<script type=\"application/json\" id=\"jmclbench-data\">(.*?)</script>")
                .matcher(Files.readString(page.resolve("index.html")));
        assertTrue(m.find());
        Map<String, Integer> out = new java.util.TreeMap<>();
        for (JsonNode c : new ObjectMapper().readTree(m.group(1)).get("cells")) {
            if (c.get("policy").asText().equals("skip") && c.get("particles").asInt() == 400) {
                out.put(c.get("config").asText(), c.get("ok").asInt());
            }
        }
        return out;
    }

    @Test
    void summaryJsonStandsInForMissingMetricRows() throws Exception {
        Path bare = Files.copy(db, dir.resolve("bare.db"));
        try (var c = java.sql.DriverManager.getConnection("jdbc:sqlite:" + bare); var st = c.createStatement()) {
            st.execute("DELETE FROM metrics");
        }
        try (StoredRuns full = StoredRuns.open(db, "--db"); StoredRuns summaryOnly = StoredRuns.open(bare, "--db")) {
            List<StoredRun> a = full.runs();
            List<StoredRun> b = summaryOnly.runs();
            assertEquals(a.size(), b.size());
            int compared = 0;
            for (int i = 0; i < a.size(); i++) {
                assertTrue(b.get(i).metrics.isEmpty());
                for (Metric m : Metric.values()) {
                    Double x = m.of(a.get(i));
                    Double y = m.of(b.get(i));
                    assertEquals(x, y, m + " of " + a.get(i).runKey);
                    compared += x == null ? 0 : 1;
                }
            }
            assertTrue(compared > 500, "values compared: " + compared);
        }
    }

    @Test
    void defaultFolderIsBesideTheDatabase() throws Exception {
        Path other = Files.createDirectories(dir.resolve("elsewhere"));
        Path copy = Files.copy(db, other.resolve("results.db"));
        assertEquals(0, JmclbenchCli.execute("report", "--db", copy.toString(), "--no-export"));
        assertTrue(Files.isRegularFile(other.resolve("report/index.html")));
        assertFalse(Files.exists(other.resolve("report/charts")), "--no-export writes the page alone");
    }

    @Test
    void missingDatabaseIsOneLineAndExitTwo() {
        String err = refusal("report", "--db", dir.resolve("nope.db").toString(),
                "--out", dir.resolve("r2").toString());
        assertEquals(1, err.strip().lines().count(), err);
        assertTrue(err.contains("--db") && err.contains("nope.db"), err);
        assertFalse(Files.exists(dir.resolve("r2")), "nothing written for bad input");
    }

    /**
     * An --out that cannot be made (below a file) is refused at once: without the check the store was read
     * and the model built, then the folder failed with exit code 1, or, with no store, --db was blamed.
     */
    @Test
    void anOutBelowAFileIsRefusedBeforeTheStoreIsRead() throws Exception {
        Path file = Files.writeString(dir.resolve("a-file"), "a file");
        Path below = file.resolve("report");
        for (Path store : List.of(db, dir.resolve("nope.db"))) {
            String err = refusal("report", "--db", store.toString(),
                    "--out", below.toString());
            assertEquals("jmclbench: --out: " + below + ": cannot write there (" + file + " is a file)", err.strip(),
                    "one line naming --out, and no line of the store being read");
        }
        assertEquals("a file", Files.readString(file));
    }

    @Test
    void aFileInThePlaceOfTheChartsFolderIsRefusedBeforeThePageIsWritten() throws Exception {
        Path r = Files.createDirectories(dir.resolve("charts-is-a-file"));
        Path charts = Files.writeString(r.resolve("charts"), "a file");
        assertEquals("jmclbench: --out: " + charts + ": not a folder",
                refusal("report", "--db", db.toString(), "--out", r.toString()).strip());
        assertFalse(Files.exists(r.resolve("index.html")), "no page of a report that failed");
        Path page = Files.createDirectories(dir.resolve("page-is-a-folder/index.html"));
        assertEquals("jmclbench: --out: " + page + ": a folder, where the page goes",
                refusal("report", "--db", db.toString(), "--out", page.getParent().toString(), "--no-export").strip());
    }

    @Test
    void aVerificationFileBesideTheStoreThatIsNotJsonIsOneLineNamingIt() throws Exception {
        Path results = Files.createDirectories(dir.resolve("bad-verification"));
        Path store = Files.copy(db, results.resolve("results.db"));
        Path verification = Files.writeString(results.resolve("verification.json"), "{\n  \"checks\": [\n  oops\n");
        String err = refusal("report", "--db", store.toString(),
                "--out", results.resolve("report").toString());
        assertEquals(1, err.strip().lines().count(), err);
        assertTrue(err.startsWith("jmclbench: " + verification + ":3: not JSON"), err);
        assertFalse(Files.exists(results.resolve("report/index.html")), "no page from a store whose verdicts cannot be read");
    }

    @Test
    void notADatabaseIsBadInput() throws Exception {
        Path junk = Files.writeString(dir.resolve("junk.db"), "not sqlite");
        String err = refusal("report", "--db", junk.toString(),
                "--out", dir.resolve("r3").toString());
        assertEquals(1, err.strip().lines().count(), err);
    }

    @Test
    void emptyStoreGivesAPageThatSaysSo() throws Exception {
        FixtureDb f = new FixtureDb();
        f.configs = List.of();
        Path empty = ReportFixtures.write(f, dir, "empty.db");
        assertEquals(0, JmclbenchCli.execute("report", "--db", empty.toString(), "--out", dir.resolve("r4").toString()));
        String page = Files.readString(dir.resolve("r4/index.html"));
        assertTrue(page.contains("\"runCount\":0"));
        // no run names no version: the header must not claim runs of several versions of jmclbench
        assertFalse(page.contains("more than one version"), page.substring(page.indexOf("<p class=\"meta\">"), page.indexOf("</p>", page.indexOf("<p class=\"meta\">"))));
        assertTrue(page.contains("0 runs (none yet)"));
    }

    @Test
    void aStoreOfOneRunSaysOneRunNotOneRuns() throws Exception {
        Path one = ReportFixtures.write(ReportFixtures.oneRun(), dir, "one.db");
        Fixtures.CliResult r = Fixtures.cli("report", "--db", one.toString(), "--out", dir.resolve("r5").toString(), "--no-export");
        assertEquals(0, r.exitCode(), r.err());
        String summary = r.out();
        assertTrue(summary.contains(" (1 run, "), summary);
        String page = Files.readString(dir.resolve("r5/index.html"));
        String header = page.substring(page.indexOf("<p class=\"meta\">"), page.indexOf("</p>", page.indexOf("<p class=\"meta\">")));
        assertTrue(header.contains(", 1 run ("), header);
        Matcher plural = Pattern.compile("\\b1 runs\\b").matcher(page);
        assertFalse(plural.find(), "a count of one with a plural noun: " + (plural.find(0) ? page.substring(Math.max(0, plural.start() - 80), plural.end()) : ""));
    }

    /** What the report command printed to stderr, with exit code 2 (bad input) asserted. */
    static String refusal(String... args) {
        Fixtures.CliResult r = Fixtures.cli(args);
        assertEquals(2, r.exitCode(), r.err());
        return r.err();
    }
}
