package org.jmclbench.tooling.report;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.TreeMap;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import org.jmclbench.tooling.store.StoredRun;
import org.jmclbench.tooling.store.StoredRuns;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.TestInstance;
import org.junit.jupiter.api.io.TempDir;

/**
 * The evaluation document on a fixture store: each table has the rows the store holds and each
 * claim's number is the store's, recomputed here from the runs themselves (not from ReportModel).
 */
@TestInstance(TestInstance.Lifecycle.PER_CLASS)
class EvaluationDocumentTest {

    /** One store and one document for all tests (writing the figures takes seconds on a loaded VM). */
    @TempDir
    static Path dir;

    private Path db;
    private String doc;
    private List<StoredRun> runs;

    /**
     * native, one JVM with both engines and all four memory styles and the rtsj engine (preallocated
     * only), a JVM with three collectors, hvm.
     */
    static FixtureDb evaluationStore() {
        FixtureDb f = new FixtureDb();
        f.configs = ReportFixtures.memoryModels("default");
        f.configs.addAll(List.of(
                new FixtureDb.Config("temurin-25", "default", "25+36", 1.1, "ok", "rtsj", "preallocated"),
                new FixtureDb.Config("temurin-21", "g1", "21.0.5", 1.2, "ok"),
                new FixtureDb.Config("temurin-21", "zgc", "21.0.5", 1.1, "ok"),
                new FixtureDb.Config("temurin-21", "serial", "21.0.5", 1.4, "ok"),
                new FixtureDb.Config("hvm", "", "icecap", 1.05, "ok", "scj", "preallocated")));
        f.policies = List.of("skip", "terminate");
        f.particles = List.of(100, 400, 1600);
        f.repetitions = 3;
        f.durationS = 6;
        f.unattributed = (cfg, rep) -> cfg.runtime().equals("hvm") && rep == 3;
        return f;
    }

    @BeforeAll
    void write() throws Exception {
        db = ReportFixtures.write(evaluationStore(), dir, "evaluation.db");
        Path verification = dir.resolve("verification.json");
        Files.writeString(verification, """
                {"schema": 1, "finished": "2026-11-23T13:00:00Z", "passed": false, "checks": [
                  {"catalog": "mission", "id": "mission-skip", "property": "P1 no deadlock", "policy": "skip",
                   "kind": "jpf", "seeded": false, "verdict": "holds", "passed": true, "seconds": 5.0,
                   "scope": "2 odometry + 0 laser events", "states": 1200},
                  {"catalog": "mission", "id": "mission-terminate", "property": "P3 abort leaves robot unchanged",
                   "policy": "terminate", "kind": "jpf", "seeded": false, "verdict": "FAILS", "passed": false,
                   "seconds": 2.0, "scope": "1 odometry + 1 laser events", "states": 34},
                  {"catalog": "mission", "id": "P4-static-abort-poll", "property": "P4 every loop polls", "policy": "-",
                   "kind": "static", "seeded": false, "verdict": "holds", "passed": true, "seconds": 0.1},
                  {"catalog": "seeded", "id": "mission-seeded-lock-inversion", "property": "P1 no deadlock",
                   "policy": "queue", "kind": "jpf", "seeded": true, "verdict": "caught", "passed": true,
                   "seconds": 3.0, "scope": "1 odometry + 1 laser events", "states": 967},
                  {"catalog": "rtsj", "id": "rtsj-thesis-queue", "property": "P1 no deadlock", "policy": "queue",
                   "kind": "jpf", "seeded": false, "verdict": "holds", "passed": true, "seconds": 1.0,
                   "scope": "thesis design, 1 odometry + 1 laser events", "states": 500},
                  {"catalog": "seeded", "id": "toy-skip", "property": "P1 no deadlock", "policy": "skip",
                   "kind": "jpf", "seeded": false, "verdict": "holds", "passed": true, "seconds": 0.5,
                   "scope": "toy", "states": 40}
                ], "abortBounds": [
                  {"engine": "javase", "memory": "preallocated", "steps": 64, "at": "A.b:1"},
                  {"engine": "scj", "memory": "preallocated", "steps": null, "at": "C.d:2"}
                ]}""");
        EvaluationDocument.write(db, "evaluation.db", dir.resolve("docs/EVALUATION.md"), dir.resolve("docs/evaluation"),
                List.of("only match-quick"), verification, new EvaluationDocument.Previous(null, "evaluation/previous.db.gz"));
        doc = Files.readString(dir.resolve("docs/EVALUATION.md"));
        String keep = System.getProperty("evaluation.keep"); // to look at the document and its figures
        if (keep != null) {
            Path to = Path.of(keep);
            try (var files = Files.walk(dir.resolve("docs"))) {
                for (Path p : files.toList()) {
                    Path t = to.resolve(dir.resolve("docs").relativize(p).toString());
                    if (Files.isDirectory(p)) {
                        Files.createDirectories(t);
                    } else {
                        Files.copy(p, t, java.nio.file.StandardCopyOption.REPLACE_EXISTING);
                    }
                }
            }
        }
        try (StoredRuns store = StoredRuns.open(db, "--db")) {
            runs = store.runs();
        }
    }

    /** Mean of a metric over the ok runs of one configuration, policy and count, straight from the runs. */
    private Double mean(String config, String policy, int particles, Metric m) {
        List<Double> xs = runs.stream().filter(r -> r.ok() && r.config().equals(config) && r.policy.equals(policy)
                && r.particles == particles).map(m::of).filter(v -> v != null).toList();
        return xs.isEmpty() ? null : xs.stream().mapToDouble(Double::doubleValue).average().orElseThrow();
    }

    private double maxOf(String config, String policy, int particles, Metric m) {
        return runs.stream().filter(r -> r.ok() && r.config().equals(config) && r.policy.equals(policy) && r.particles == particles)
                .map(m::of).mapToDouble(Double::doubleValue).max().orElseThrow();
    }

    private String nativeConfig() {
        return configs().stream().filter(c -> c.startsWith("native")).findFirst().orElseThrow();
    }

    private List<String> configs() {
        return runs.stream().map(StoredRun::config).distinct().toList();
    }

    /** The rows of the table that follows {@code caption}, as cells (header and rule left out). */
    private List<List<String>> table(String caption) {
        return table(doc, caption);
    }

    private static List<List<String>> table(String doc, String caption) {
        int at = doc.indexOf(caption);
        assertTrue(at >= 0, "no " + caption + " in\n" + doc);
        String[] lines = doc.substring(at).split("\n");
        List<List<String>> rows = new ArrayList<>();
        int i = 1;
        while (i < lines.length && !lines[i].startsWith("|")) {
            i++;
        }
        i += 2; // header and rule
        for (; i < lines.length && lines[i].startsWith("|"); i++) {
            List<String> cells = new ArrayList<>();
            for (String c : lines[i].substring(1, lines[i].length() - 1).split("(?<!\\\\)\\|")) {
                cells.add(c.strip());
            }
            rows.add(cells);
        }
        return rows;
    }

    private static String num(double v, int decimals) {
        return String.format(Locale.ROOT, "%." + decimals + "f", v);
    }

    @Test
    void documentHasMethodResultsThreatsConclusionsInOrder() {
        int method = doc.indexOf("## 1. Method");
        int results = doc.indexOf("## 2. Results");
        int threats = doc.indexOf("## 3. Threats to validity");
        int conclusions = doc.indexOf("## 4. Conclusions");
        assertTrue(method > 0 && method < results && results < threats && threats < conclusions, doc);
        assertTrue(doc.contains("- only match-quick"), "the cuts are in the method");
    }

    @Test
    void configurationTableHasEveryConfigurationWithItsRunCounts() {
        List<List<String>> rows = table("**Configurations**");
        assertEquals(configs().size(), rows.size());
        for (String c : configs()) {
            long n = runs.stream().filter(r -> r.config().equals(c)).count();
            assertTrue(rows.stream().anyMatch(r -> r.get(0).equals(c) && r.get(2).equals(String.valueOf(n))), c + " with " + n + " runs");
        }
    }

    @Test
    void missTableHoldsEveryConfigurationAndTheStoresMeans() {
        List<List<String>> rows = table("Table 4:");
        assertEquals(configs().size(), rows.size(), "one row per configuration of the skip runs");
        List<Integer> counts = List.of(100, 400, 1600);
        for (List<String> row : rows) {
            for (int i = 0; i < counts.size(); i++) {
                Double m = mean(row.get(0), "skip", counts.get(i), Metric.MISS_COUNT);
                assertTrue(row.get(i + 1).startsWith(num(m, 1) + " ["), row.get(0) + " at " + counts.get(i) + ": " + row.get(i + 1));
            }
        }
    }

    @Test
    void missCountClaimNamesTheLowestMeanAndTheHighestMeanAsSuch() {
        Matcher m = Pattern.compile("At 1600 particles \\(the heaviest load of the sweep\\), the lowest mean missCount "
                + "\\(dropped jobs per run\\) is \\*\\*(.+?)\\*\\*'s: ([0-9.]+) \\[[^]]*\\]; the highest mean is "
                + "\\*\\*(.+?)\\*\\*'s: ([0-9.]+) ").matcher(doc);
        assertTrue(m.find(), doc);
        double min = configs().stream().mapToDouble(c -> mean(c, "skip", 1600, Metric.MISS_COUNT)).min().orElseThrow();
        double max = configs().stream().mapToDouble(c -> mean(c, "skip", 1600, Metric.MISS_COUNT)).max().orElseThrow();
        assertTrue(min < max, "the fixture's configurations differ in their mean missCount");
        assertEquals(num(min, 1), m.group(2));
        assertEquals(num(min, 1), num(mean(m.group(1), "skip", 1600, Metric.MISS_COUNT), 1), "the lowest named has the lowest mean");
        assertEquals(num(max, 1), m.group(4));
        assertEquals(num(max, 1), num(mean(m.group(3), "skip", 1600, Metric.MISS_COUNT), 1), "the highest named has the highest mean");
        // three runs a side separate nothing: a lowest mean is not "the fewest"
        assertFalse(doc.toLowerCase(Locale.ROOT).contains("fewest"), "a mean over repetitions is called the lowest mean");
        assertTrue(doc.contains("- Lowest mean missCount (dropped jobs per run, skip) at 1600 particles: " + m.group(1) + " ("), doc);
    }

    @Test
    void withoutQueueRunsNoBreakdownLoadIsClaimedAndNoLoadUnderSkipStandsInForIt() {
        assertTrue(doc.contains("The store has no run under the queue policy, so no breakdown load is known."), doc);
        assertFalse(doc.contains("sustainable-load"), "the largest load with no miss under skip measured the dataset, not the runtime");
    }

    @Test
    void deadlineAccountingGivesEachTasksMissRatioAndResponseTimeOverReleasedJobs() {
        List<List<String>> rows = table("Table 2:");
        assertFalse(rows.isEmpty());
        for (List<String> row : rows) {
            int n = 1600;
            List<StoredRun> cell = runs.stream().filter(r -> r.ok() && r.config().equals(row.get(0)) && r.policy.equals(row.get(1))
                    && r.particles == n).toList();
            double missed = cell.stream().mapToDouble(r -> TaskMetric.DEADLINE_MISSES.of(r, "predict")).sum();
            double released = cell.stream().mapToDouble(r -> r.summary().at("/tasks/predict/released").asDouble()).sum();
            assertTrue(row.get(3).startsWith(num(100 * missed / released, 2) + " ["), "pooled over the repetitions: " + row);
            boolean dropped = runs.stream().anyMatch(r -> r.ok() && r.config().equals(row.get(0)) && r.policy.equals(row.get(1))
                    && r.particles == n && Double.isInfinite(TaskMetric.RESPONSE_P99.of(r, "update")));
            assertEquals(dropped, row.get(6).startsWith("∞"), "a run whose top 1% holds a dropped job has no finite p99: " + row);
        }
    }

    @Test
    void terminationGivesEachConfigurationsAbortLatencyUnderTerminate() {
        List<List<String>> rows = table("Table 6b:");
        assertFalse(rows.isEmpty());
        for (List<String> row : rows) {
            List<StoredRun> cell = runs.stream().filter(r -> r.ok() && r.config().equals(row.get(0)) && r.policy.equals("terminate")
                    && r.particles == 1600).toList();
            java.util.OptionalDouble p50 = cell.stream().map(r -> TaskMetric.ABORT_P50.of(r, "all")).filter(v -> v != null)
                    .mapToDouble(Double::doubleValue).average();
            // four decimals of a ms: the evaluation's abort latencies are microseconds, and three decimals wrote
            // a stopping of 0.3 us as "0.000 [0.000, 0.000]" and 2.4 against 2.6 us both as "0.002"
            assertEquals(p50.isPresent() ? num(p50.getAsDouble(), 4) : "n/a", row.get(3).split(" ")[0], row.toString());
            // runs that recorded seen_ns add noticed p50, p99 and max and stopping max before the bound
            boolean split = row.size() == 12;
            int boundColumn = split ? 10 : 6;
            // verify's bound: 64 steps for javase, the whole job for scj (this file's), none for C or other styles
            String engine = row.get(0).contains("/ javase preallocated") ? "javase"
                    : row.get(0).contains("/ scj preallocated") || row.get(0).startsWith("hvm") ? "scj" : null;
            if (engine == null || row.get(0).startsWith("native")) {
                assertEquals("-", row.get(boundColumn), row.toString());
                continue;
            }
            double slowest = cell.stream().flatMap(r -> java.util.stream.Stream.of(TaskMetric.LATENCY_MAX.of(r, "predict"),
                    TaskMetric.LATENCY_MAX.of(r, "update"))).mapToDouble(Double::doubleValue).max().orElseThrow();
            double bound = engine.equals("javase") ? 64 * slowest / 1600 : slowest;
            assertEquals((engine.equals("javase") ? "64 particle steps: " : "the whole job: ") + num(bound, 4) + " ms",
                    row.get(boundColumn));
            // the bound bounds noticing (its p50, p99 and max) where the runs recorded it, else the whole abort latency
            List<TaskMetric> compared = split ? List.of(TaskMetric.ABORT_NOTICE_P50, TaskMetric.ABORT_NOTICE_P99,
                    TaskMetric.ABORT_NOTICE_MAX) : List.of(TaskMetric.ABORT_MAX);
            List<String> verdicts = new java.util.ArrayList<>();
            for (TaskMetric m : compared) {
                double max = cell.stream().map(r -> m.of(r, "all")).filter(v -> v != null)
                        .mapToDouble(Double::doubleValue).max().orElse(Double.NaN);
                // a "no" beside a mean under the bound gives the run's value that is over it
                verdicts.add(Double.isNaN(max) ? "-" : max <= bound ? "yes" : "no (" + num(max, 4) + ")");
            }
            String expected = verdicts.contains("-") ? "-" : String.join(" / ", verdicts);
            assertEquals(expected, row.get(boundColumn + 1), row.toString());
        }
        assertTrue(doc.contains("(evaluation/abort-latency-1600.svg)") || rows.stream().allMatch(r -> r.get(3).equals("n/a")));
    }

    @Test
    void whatRunsWhereHasARowPerConfiguration() {
        List<List<String>> rows = table("**What runs where.**");
        assertEquals(configs().size(), rows.size());
        List<String> c = rows.stream().filter(r -> r.get(0).startsWith("native")).findFirst().orElseThrow();
        assertTrue(c.get(1).startsWith("C, compiled ahead of time"), c.toString());
        List<String> hvm = rows.stream().filter(r -> r.get(0).startsWith("hvm")).findFirst().orElseThrow();
        assertTrue(hvm.get(4).startsWith("real SCJ memory areas"), hvm.toString());
    }

    @Test
    void latencyTableIsAtTheLargestCountWhereCMissedNothingWithTheStoresMeans() {
        int ref = 0;
        for (int n : List.of(100, 400, 1600)) {
            if (maxOf(nativeConfig(), "skip", n, Metric.MISS_COUNT) == 0) {
                ref = n;
            }
        }
        assertTrue(ref > 0, "the fixture's C baseline misses nothing at 100 particles");
        List<List<String>> rows = table("Table 3: task latency and release jitter at " + ref + " particles");
        assertEquals(configs().size(), rows.size());
        double c = mean(nativeConfig(), "skip", ref, Metric.LATENCY_MEAN);
        for (List<String> row : rows) {
            double lat = mean(row.get(0), "skip", ref, Metric.LATENCY_MEAN);
            assertTrue(row.get(1).startsWith(num(lat, 3) + " ["), row.toString());
            assertTrue(row.get(5).startsWith(num(mean(row.get(0), "skip", ref, Metric.JITTER_P99), 3)), row.toString());
            assertEquals(num(lat / c, 2) + "x", row.get(6));
        }
        assertTrue(doc.contains("(evaluation/spectrum-skip-" + ref + ".svg)"));
        // the count is chosen by missCount, under skip the dropped jobs: a late job is no deadline met
        assertTrue(doc.contains(ref + " particles is the largest count of the sweep at which the C baseline dropped no job"), doc);
        assertFalse(doc.contains("missed no deadline"), "missCount under skip does not count the late jobs");
    }

    @Test
    void latencyClaimNamesTheLowestMeanP99AndCallsNoConfigurationBest() {
        String section = doc.substring(doc.indexOf("### 2.3"), doc.indexOf("### 2.4"));
        int ref = Integer.parseInt(section.replaceAll("(?s).*Table 3: task latency and release jitter at ([0-9]+) particles.*", "$1"));
        Matcher m = Pattern.compile("the lowest mean p99 task latency of the Java configurations is \\*\\*(.+?)\\*\\*'s")
                .matcher(section);
        assertTrue(m.find(), section);
        double lowest = configs().stream().filter(c -> !c.startsWith("native"))
                .mapToDouble(c -> mean(c, "skip", ref, Metric.LATENCY_P99)).min().orElseThrow();
        assertEquals(num(lowest, 3), num(mean(m.group(1), "skip", ref, Metric.LATENCY_P99), 3), m.group(1));
        // three runs a side separate nothing from the next lowest: no "best"
        assertFalse(section.contains("best"), section);
        assertTrue(section.contains("so the p99 of the Java configuration with the lowest mean p99 is "), section);
    }

    @Test
    void scjCostComparesTheSameJvmAtTheSameCount() {
        List<List<String>> rows = table("Table 5:");
        assertEquals(3, rows.size(), "temurin-25 at three counts (hvm is not a JVM)");
        for (List<String> row : rows) {
            assertEquals("temurin-25/default", row.get(0));
            int n = Integer.parseInt(row.get(1));
            double se = mean("temurin-25/default / javase preallocated", "skip", n, Metric.LATENCY_MEAN);
            double scj = mean("temurin-25/default / scj preallocated", "skip", n, Metric.LATENCY_MEAN);
            assertEquals(num(scj / se, 2) + "x", row.get(4));
        }
    }

    @Test
    void hvmIsComparedWithScjOnTheJvm() {
        List<List<String>> rows = table("Table 5b:");
        assertEquals(6, rows.size(), "hvm and temurin-25 scj at three counts");
        List<String> hvm1600 = rows.stream().filter(r -> r.get(0).startsWith("hvm") && r.get(1).equals("1600")).findFirst().orElseThrow();
        assertTrue(hvm1600.get(3).startsWith(num(mean(hvm1600.get(0), "skip", 1600, Metric.LATENCY_MEAN), 3)));
    }

    @Test
    void memoryExperimentHasEveryStyleOfTheJvmWithItsAreas() throws Exception {
        List<List<String>> rows = table("Table 10:");
        assertEquals(4 * 3, rows.size(), "four styles of temurin-25 at three counts");
        for (List<String> row : rows) {
            int n = Integer.parseInt(row.get(1));
            assertTrue(row.get(2).startsWith(num(mean(row.get(0), "skip", n, Metric.MISS_COUNT), 1)), row.toString());
        }
        assertTrue(rows.stream().filter(r -> r.get(0).contains("scj scoped")).allMatch(r -> r.get(5).contains("mission")),
                "the SCJ rows name their areas");
        assertTrue(Files.size(dir.resolve("docs/evaluation/memory-1600.svg")) > 1000);
        assertTrue(rows.stream().noneMatch(r -> r.get(0).contains("rtsj")), "an engine with one memory style is no memory style");
    }

    @Test
    void aMemoryStyleIsComparedWithItsOwnEnginesPreallocatedOnly() {
        String section = doc.substring(doc.indexOf("### 2.10"), doc.indexOf("### 2.11"));
        List<String> comparisons = section.lines().filter(l -> l.startsWith("- ")).toList();
        assertEquals(List.of("- temurin-25/default / javase allocating against temurin-25/default / javase preallocated",
                        "- temurin-25/default / scj scoped against temurin-25/default / scj preallocated"),
                comparisons.stream().map(l -> l.substring(0, l.indexOf(':'))).toList(), section);
        String javase = comparisons.get(0);
        assertTrue(javase.contains("mean task latency " + num(mean("temurin-25/default / javase allocating", "skip", 1600,
                Metric.LATENCY_MEAN), 3) + " ["), javase);
        String finding = doc.lines().filter(l -> l.startsWith("- Memory model at 1600 particles")).findFirst().orElseThrow();
        double ratio = mean("temurin-25/default / javase allocating", "skip", 1600, Metric.LATENCY_MEAN)
                / mean("temurin-25/default / javase preallocated", "skip", 1600, Metric.LATENCY_MEAN);
        assertTrue(finding.contains("temurin-25/default / javase allocating " + num(ratio, 2) + "x ("), finding);
        assertFalse(finding.contains("rtsj"), finding);
    }

    @Test
    void policiesAndCollectorsHaveTheirRows() {
        assertEquals(configs().size() * 3 * 2, table("Table 6:").size(), "every configuration ran skip and terminate at three counts");
        List<List<String>> gc = table("Table 11:");
        assertEquals(3 * 3, gc.size(), "temurin-21 with three collectors at three counts");
        assertTrue(gc.stream().allMatch(r -> r.get(0).startsWith("temurin-21/")));
    }

    @Test
    void attributionRowsAreTheStoresMeanCausesAtTheHeaviestCount() {
        List<List<String>> rows = table("Table 12:");
        assertFalse(rows.isEmpty());
        String header = doc.substring(doc.indexOf("Table 12:")).split("\n")[2];
        List<String> kinds = new ArrayList<>();
        for (String h : header.substring(1, header.length() - 1).split("\\|")) {
            kinds.add(h.strip());
        }
        assertEquals("runs attributed", kinds.get(1));
        for (int i = 2; i < kinds.size(); i++) {
            final int k = i;
            assertTrue(rows.stream().anyMatch(r -> !r.get(k).isEmpty()), "a column of no primary cause: " + kinds.get(k));
        }
        for (List<String> row : rows) {
            Map<String, Double> sum = new TreeMap<>();
            int attributed = 0;
            int completed = 0;
            for (StoredRun r : runs) {
                if (r.ok() && r.config().equals(row.get(0)) && r.policy.equals("skip") && r.particles == 1600) {
                    completed++;
                    if (!r.metrics.containsKey("run/cause.jobs/count")) {
                        continue; // no evidence, not zero causes: the mean leaves it out
                    }
                    attributed++;
                    r.metrics.forEach((k, v) -> {
                        if (k.startsWith("run/cause.") && k.endsWith("/primary")) {
                            sum.merge(k.substring(10, k.length() - 8), v, Double::sum);
                        }
                    });
                }
            }
            assertEquals(attributed + " of " + completed, row.get(1), row.get(0));
            for (int i = 2; i < kinds.size(); i++) {
                Double s = sum.get(kinds.get(i));
                // a cause that was never the primary one is blank, as one not recorded: the evaluation's
                // "0.0" beside blanks read as two different things (and as a rounded small count)
                assertEquals(s == null || s == 0 ? "" : num(s / attributed, 1), row.get(i), row.get(0) + " " + kinds.get(i));
            }
            final int n = attributed;
            Map.Entry<String, Double> top = sum.entrySet().stream().max(Map.Entry.comparingByValue()).orElseThrow();
            double total = sum.values().stream().mapToDouble(Double::doubleValue).sum();
            assertTrue(doc.contains("- " + row.get(0) + ": " + num(top.getValue() / n, 1) + " of " + num(total / n, 1)
                    + " attributed jobs per run were " + top.getKey() + "."), "dominant cause of " + row.get(0));
        }
        assertTrue(rows.stream().anyMatch(r -> r.get(0).startsWith("hvm ") && r.get(1).equals("2 of 3")), rows.toString());
    }

    @Test
    void verificationAndDoctorFindingsAreReported() {
        List<List<String>> rows = table("Table 13:");
        assertEquals(6, rows.size());
        assertEquals(List.of("mission-terminate", "mission", "P3 abort leaves robot unchanged", "terminate",
                "1 odometry + 1 laser events", "FAILS", "34", "2.0"), rows.get(1));
        assertEquals("seeded bug", rows.get(3).get(1));
        assertEquals("rtsj engine", rows.get(4).get(1), "the rtsj engine's checks are not the toy program's");
        assertEquals("toy program", rows.get(5).get(1));
        assertTrue(doc.contains("On the real mission 2 of 3 checks hold, over 1234 states; on the rtsj engine 1 of 1 "
                + "checks hold, over 500 states; 1 of 1 seeded bugs were caught"), doc);
        assertTrue(doc.contains("| bench-host | virtualization | warn | kvm |"), "the doctor's warning is a threat");
        assertTrue(doc.contains("A 2-processor machine"));
    }

    @Test
    void theEnginesSaidToCarryNoCpuTimeAreThoseWhoseRunsRecordedNone() throws Exception {
        // every fixture run's summary says cpuTime used, the rtsj and scj ones too: no engine is named
        assertFalse(doc.contains("carry no CPU time"), "the rtsj and scj runs of the fixture recorded CPU time");
        Path edited = Files.copy(db, dir.resolve("no-cpu.db"));
        try (var c = java.sql.DriverManager.getConnection("jdbc:sqlite:" + edited); var st = c.createStatement()) {
            st.execute("UPDATE runs SET summary_json = replace(summary_json, '\"cpuTime\":\"used (allocation-free)\"',"
                    + " '\"cpuTime\":\"unavailable (RTSJ 1.0.2 has no per-thread CPU clock)\"') WHERE engine = 'rtsj'");
        }
        String other = document(edited, "no-cpu.db", dir.resolve("no-cpu"));
        assertTrue(other.contains("The jobs of the rtsj engine carry no CPU time in these runs"), other);
    }

    @Test
    void aSectionNamesOnlyTheTablesAndFiguresItHas() throws Exception {
        // a section with no data printed "(Table 12, Figure 12)" under its heading and neither below it
        String small = document(ReportFixtures.write(ReportFixtures.engines(), dir, "sections.db"), "sections.db", dir.resolve("sections"));
        int empty = 0;
        for (String heading : small.lines().filter(l -> l.startsWith("### ")).toList()) {
            Matcher m = Pattern.compile("\\((Table [0-9a-z]+)(?:, (Figure [0-9a-z]+))?\\)$").matcher(heading);
            if (!m.find()) {
                empty++;
                continue;
            }
            assertTrue(small.contains("\n" + m.group(1) + ":"), heading + ": no " + m.group(1));
            assertTrue(m.group(2) == null || small.contains("*" + m.group(2) + ":"), heading + ": no " + m.group(2));
        }
        assertTrue(empty > 0, "the small store leaves some section without data");
    }

    @Test
    void figuresOfAnEarlierStoreAreRemoved() throws Exception {
        Path small = ReportFixtures.write(ReportFixtures.engines(), dir, "stale.db");
        Path out = dir.resolve("stale");
        Files.createDirectories(out.resolve("evaluation"));
        Files.writeString(out.resolve("evaluation/memory-99999.svg"), "<svg/>");
        String doc = document(small, "small.db", out);
        assertFalse(Files.exists(out.resolve("evaluation/memory-99999.svg")), "a figure the document no longer shows");
        try (var written = Files.list(out.resolve("evaluation"))) {
            written.filter(f -> f.toString().endsWith(".svg"))
                    .forEach(f -> assertTrue(doc.contains("evaluation/" + f.getFileName()), f + " is not in the document"));
        }
    }

    @Test
    void aStoreOfOneRunAndOneRepetitionSaysSoInTheSingular() throws Exception {
        Path one = ReportFixtures.write(ReportFixtures.oneRun(), dir, "one.db");
        Path out = dir.resolve("one");
        String d = document(one, "one.db", out);
        assertTrue(d.contains("**Runs.** 1 run in the store, 1 completed. Each configuration and setting completed 1 repetition;"), d);
        ReportModel.Cell c = new ReportModel.Cell();
        c.metrics.put(TaskMetric.RESPONSE_P99.key("all"),
                new ReportModel.Agg(1, Double.POSITIVE_INFINITY, null, null, 1.0, Double.POSITIVE_INFINITY, new double[] {Double.POSITIVE_INFINITY}));
        assertEquals("∞ (in at least one of 1 run)", EvaluationQuestions.response(c, "all"));
    }

    @Test
    void missingHvmAndVerificationAreSaidNotInvented() throws Exception {
        Path small = ReportFixtures.write(ReportFixtures.engines(), dir, "small.db");
        Path out = dir.resolve("small");
        String d = document(small, "small.db", out);
        assertTrue(d.contains("**No data.** The store holds no completed run of the `hvm` runtime"), d);
        assertTrue(d.contains("none.json` does not exist"), d);
        assertTrue(d.contains("no JVM that ran several collectors"), d);
        assertFalse(d.contains("Table 5b:") || d.contains("Table 13:"));
    }

    @Test
    void aBracketSaysHowItsUpperCountWasLateAndALateJobOrTwoIsNoSeparation() throws Exception {
        FixtureDb f = ReportFixtures.breakdown();
        Path queue = ReportFixtures.write(f, dir, "queue.db");
        Path out = dir.resolve("queue");
        String d = document(queue, "queue.db", out);
        List<StoredRun> stored;
        try (StoredRuns store = StoredRuns.open(queue, "--db")) {
            stored = store.runs();
        }
        List<List<String>> rows = table(d, "Table 1:");
        assertEquals(f.configs.size(), rows.size(), d);
        List<String> marginal = new ArrayList<>();
        for (List<String> row : rows) {
            // the first count at which a run had a late job, straight from the runs
            int fails = stored.stream().filter(r -> r.config().equals(row.get(0)) && Metric.MISS_COUNT.of(r) > 0)
                    .mapToInt(r -> r.particles).min().orElseThrow();
            List<Double> late = stored.stream().filter(r -> r.config().equals(row.get(0)) && r.particles == fails)
                    .map(Metric.MISS_COUNT::of).toList();
            long lateRuns = late.stream().filter(v -> v > 0).count();
            long most = Math.round(late.stream().mapToDouble(Double::doubleValue).max().orElseThrow());
            assertEquals(fails + " (" + lateRuns + " of " + late.size() + " repetitions late, by " + (lateRuns == 1 ? "" : "at most ")
                    + most + (most == 1 ? " job)" : " jobs)"), row.get(2), row.get(0));
            if (lateRuns == 1 && most <= 2) {
                marginal.add(row.get(0));
            }
        }
        assertFalse(marginal.isEmpty() || marginal.size() == rows.size(), "the fixture should have both kinds: " + rows);
        // a count above the bracket that held in some repetition is said, from the runs themselves
        int notMonotone = 0;
        for (List<String> row : rows) {
            int fails = Integer.parseInt(row.get(2).split(" ")[0]);
            List<String> above = stored.stream().filter(r -> r.config().equals(row.get(0)) && r.particles > fails)
                    .map(r -> r.particles).distinct().sorted().map(p -> {
                        List<Double> late = stored.stream().filter(r -> r.config().equals(row.get(0)) && r.particles == p)
                                .map(Metric.MISS_COUNT::of).toList();
                        long held = late.stream().filter(v -> v == 0).count();
                        return held == 0 ? null : p + " held in " + held + " of " + late.size() + " repetitions";
                    }).filter(java.util.Objects::nonNull).toList();
            assertEquals(!above.isEmpty(), d.contains(row.get(0) + " failed at " + fails + ", yet above it "
                    + String.join(", ", above)), row.get(0) + ": " + above);
            notMonotone += above.isEmpty() ? 0 : 1;
        }
        assertTrue(d.contains(" " + notMonotone + " of " + rows.size() + (notMonotone == 1 ? " is" : " are")
                + " not monotone: a count above the bracket held"), d);
        assertTrue(d.contains("was late in one repetition by a job or two (" + String.join(", ", marginal) + "), the bracket rests"), d);
    }

    /**
     * The document written from {@code store} (named {@code label} in it; no cuts, no verification
     * results) into {@code out}: EVALUATION.md and its figures in evaluation/.
     */
    private String document(Path store, String label, Path out) throws Exception {
        return document(store, label, out, new EvaluationDocument.Previous(null, null));
    }

    /** {@link #document(Path, String, Path)} with the previous evaluation's data, which section 2.14 repeats the tests on. */
    private String document(Path store, String label, Path out, EvaluationDocument.Previous previous) throws Exception {
        EvaluationDocument.write(store, label, out.resolve("EVALUATION.md"), out.resolve("evaluation"), List.of(), dir.resolve("none.json"),
                previous);
        return Files.readString(out.resolve("EVALUATION.md"));
    }

    /**
     * A scheduling store: temurin-25 under default, fifo and fifo+pinned (the pinned one slower to
     * release, faster to compute: fewer dropped jobs from later releases), skip and terminate, 100
     * and 6400 particles, {@code repetitions} each; the document written from it.
     */
    private String schedulingDocument(int repetitions) throws Exception {
        FixtureDb f = new FixtureDb();
        f.configs = new ArrayList<>(List.of(
                new FixtureDb.Config("temurin-25", "default", "25+36", 2.0, "ok"),
                new FixtureDb.Config("temurin-25", "fifo", "25+36", 1.5, "ok"),
                new FixtureDb.Config("temurin-25", "fifo+pinned", "25+36", 1.0, "ok")));
        f.jitterScale = Map.of("temurin-25/fifo+pinned", 4.0);
        f.policies = List.of("skip", "terminate");
        f.particles = List.of(100, 6400);
        f.repetitions = repetitions;
        f.durationS = 6;
        Path store = ReportFixtures.write(f, dir, "scheduling-" + repetitions + ".db");
        Path out = dir.resolve("scheduling-" + repetitions);
        return document(store, "scheduling.db", out);
    }

    @Test
    void schedulingSentencesNameTheirCountAndPolicyAndClaimTheSkipEffectOnlyWhereSeparated() throws Exception {
        Pattern pinned = Pattern.compile("(?m)^At ([0-9]+) particles, policy (\\w+), under fifo\\+pinned every thread of temurin-25 .*$");
        boolean claimed = false;
        boolean withheld = false;
        for (int repetitions : List.of(3, 10)) {
            String d = schedulingDocument(repetitions);
            String section = d.substring(d.indexOf("### 2.7"), d.indexOf("### 2.8"));
            // the conclusions repeat the test's verdict on every pair: none with three runs a side
            String finding = d.lines().filter(l -> l.startsWith("- Generic vs real-time scheduling")).findFirst().orElseThrow();
            assertEquals(repetitions < Separation.MIN_REPETITIONS, finding.contains(": release jitter p99 not separated for 8 of 8 (2.7)."), finding);
            assertEquals(repetitions >= Separation.MIN_REPETITIONS, finding.contains("release jitter p99 higher for temurin-25/fifo+pinned ("), finding);
            List<List<String>> rows = table(section, "Table 7:");
            // every sentence before the table speaks of one count and policy, and Table 7 has those rows
            List<String> sentences = section.substring(0, section.indexOf("Table 7:")).lines()
                    .filter(l -> !l.isBlank() && !l.startsWith("#")).toList();
            assertFalse(sentences.isEmpty(), section);
            for (String s : sentences) {
                Matcher at = Pattern.compile("^At ([0-9]+) particles, policy (\\w+), ").matcher(s);
                assertTrue(at.find(), "a sentence of 2.7 without its count and policy: " + s);
                assertTrue(rows.stream().anyMatch(r -> r.get(1).equals(at.group(1)) && r.get(2).equals(at.group(2))), s);
            }
            Matcher m = pinned.matcher(section);
            int paragraphs = 0;
            while (m.find()) {
                paragraphs++;
                String p = m.group();
                boolean skip = m.group(2).equals("skip");
                // the effect on dropped jobs is skip's: under terminate the paragraph says nothing of it
                assertEquals(skip, p.contains("Skip drops an event"), p);
                boolean fewer = p.contains("come from later releases");
                if (skip && repetitions < Separation.MIN_REPETITIONS) {
                    assertFalse(fewer, "three runs a side separate nothing: " + p);
                }
                if (fewer) {
                    // claimed only with both tests behind it: fewer dropped jobs and a later release
                    assertTrue(p.contains("(temurin-25/fifo+pinned lower than temurin-25/default (")
                            && p.contains("(temurin-25/default lower than temurin-25/fifo+pinned ("), p);
                    claimed = true;
                } else if (skip) {
                    assertTrue(p.contains("the data do not show fewer dropped jobs under fifo+pinned")
                            || p.contains("with no later release to explain them"), p);
                    withheld = true;
                }
            }
            assertEquals(4, paragraphs, "fifo+pinned at two counts under two policies: " + section);
            // Figure 7 names the profiles it draws, from the store, not a fixed "SCHED_FIFO pinned"
            Matcher fig = Pattern.compile("\\*Figure 7: release jitter p99 per runtime under each of its profiles \\(([^)]*)\\), "
                    + "([0-9]+) particles, policy (\\w+) ").matcher(section);
            assertTrue(fig.find(), section);
            assertEquals("default, fifo, fifo+pinned", fig.group(1));
            assertTrue(rows.stream().anyMatch(r -> r.get(1).equals(fig.group(2)) && r.get(2).equals(fig.group(3))), fig.group());
        }
        assertTrue(claimed, "the ten-repetition store separates fewer dropped jobs under fifo+pinned at 6400 particles");
        assertTrue(withheld, "the three-repetition store separates nothing");
    }

    /**
     * A load takes the CPU from the thread that releases a job as well as from the job, so section 2.8 compares
     * both: here the cpu load makes native's releases eight times later and leaves temurin-25's alone.
     */
    @Test
    void aLoadedMachineIsComparedOnItsReleaseJitterBesideItsLatency() throws Exception {
        FixtureDb f = new FixtureDb();
        f.configs = new ArrayList<>(List.of(new FixtureDb.Config("native", "", "gcc 12.2.0", 1.0, "ok"),
                new FixtureDb.Config("temurin-25", "default", "25+36", 1.2, "ok")));
        f.loads = List.of("none", "cpu");
        f.jitterScale = Map.of("native [load cpu]", 8.0);
        String d = comparisonDocument(f, "load");
        String section = d.substring(d.indexOf("### 2.8"), d.indexOf("### 2.9"));
        for (String config : List.of("native", "temurin-25/default")) {
            for (String metric : List.of("task latency p99", "release jitter p99")) {
                String start = "At 6400 particles, policy skip, " + metric + ": " + config + " ";
                assertTrue(section.lines().anyMatch(l -> l.startsWith(start) && l.contains(" against " + config + " [load cpu] ")),
                        start + "... missing from " + section);
            }
        }
        String jitter = section.lines().filter(l -> l.startsWith("At 6400 particles, policy skip, release jitter p99: native ")).findFirst().orElseThrow();
        assertTrue(jitter.contains("): native lower than native [load cpu] (p "), jitter);
        String unmoved = section.lines().filter(l -> l.startsWith("At 6400 particles, policy skip, release jitter p99: temurin-25/default ")).findFirst().orElseThrow();
        assertTrue(unmoved.contains("): not separated"), unmoved);
        // and the conclusions say which pairs the test separates
        String finding = d.lines().filter(l -> l.startsWith("- An idle vs a loaded machine")).findFirst().orElseThrow();
        assertTrue(finding.contains("(the pairs of Table 8): release jitter p99 higher for native [load cpu] ("), finding);
        assertTrue(finding.contains("x); not separated for 1 of 2; task latency p99 "), finding);
    }

    /**
     * noidle beside each runtime's default (section 2.7), on both metrics: here the CPUs kept awake
     * make native's releases three times less late and its jobs a fifth faster, and leave temurin-25
     * alone; the conclusions repeat the verdicts, and the fifo pairs are untouched by it.
     */
    @Test
    void idleStatesHeldOffAreComparedWithTheDefaultOnJitterAndLatency() throws Exception {
        FixtureDb f = new FixtureDb();
        f.configs = defaultAndNoidle(0.8);
        f.configs.add(new FixtureDb.Config("temurin-25", "fifo+pinned", "25+36", 1.2, "ok"));
        f.jitterScale = Map.of("native/noidle", 0.3);
        String d = comparisonDocument(f, "noidle");
        String section = d.substring(d.indexOf("### 2.7"), d.indexOf("### 2.8"));
        for (String[] pair : List.of(new String[] {"native", "native/noidle"}, new String[] {"temurin-25/default", "temurin-25/noidle"})) {
            for (String metric : List.of("task latency p99", "release jitter p99")) {
                String start = "At 6400 particles, policy skip, " + metric + ": " + pair[0] + " ";
                assertTrue(section.lines().anyMatch(l -> l.startsWith(start) && l.contains(" against " + pair[1] + " ")),
                        start + "... against " + pair[1] + " missing from " + section);
            }
        }
        // the fifo pair keeps the default as its base, not the noidle profile beside it
        assertTrue(section.lines().anyMatch(l -> l.startsWith("At 6400 particles, policy skip, release jitter p99: temurin-25/default ")
                && l.contains(" against temurin-25/fifo+pinned ")), section);
        List<List<String>> rows = table(section, "Table 7:");
        assertEquals(List.of("native", "native/noidle", "temurin-25/default", "temurin-25/fifo+pinned", "temurin-25/noidle"),
                rows.stream().map(r -> r.get(0)).sorted().toList(), "each configuration once: " + rows);
        assertTrue(section.contains("and with its CPUs kept out of deep idle states (`noidle`)"), section);
        String finding = d.lines().filter(l -> l.startsWith("- CPU idle states")).findFirst().orElseThrow();
        assertTrue(finding.contains("(Table 7): release jitter p99 lower for native/noidle ("), finding);
        assertTrue(finding.contains("x); not separated for 1 of 2; task latency p99 lower for native/noidle ("), finding);
        assertTrue(d.lines().anyMatch(l -> l.startsWith("- Generic vs real-time scheduling, each fifo profile")), d);
    }

    /**
     * A load that makes jobs faster (2.8) is put down to idle states only where noidle does the same on the
     * idle machine (2.7): native's jobs cost a fifth less beside the cpu load and under noidle, temurin-25's
     * beside the load only. Without a fifo run, 2.7 still compares noidle and draws its figure.
     */
    @Test
    void aLoadThatSpeedsJobsUpIsPutDownToIdleStatesOnlyWhereNoidleDoesTheSame() throws Exception {
        FixtureDb f = new FixtureDb();
        f.configs = defaultAndNoidle(1.0);
        f.loads = List.of("none", "cpu");
        f.costScale = Map.of("native [load cpu]", 0.8, "native/noidle", 0.8, "temurin-25/default [load cpu]", 0.8);
        String d = comparisonDocument(f, "busy");
        String load = d.substring(d.indexOf("### 2.8"), d.indexOf("### 2.9"));
        String finding = d.lines().filter(l -> l.startsWith("- An idle vs a loaded machine")).findFirst().orElseThrow();
        assertTrue(finding.contains("task latency p99 lower for native [load cpu] (") && finding.contains("temurin-25/default [load cpu] ("),
                "both loads make jobs faster: " + finding);
        List<String> explained = load.lines().filter(l -> l.contains("as it is under noidle on the idle machine (2.7)")).toList();
        assertEquals(1, explained.size(), load);
        assertTrue(explained.get(0).startsWith("native [load cpu]: task latency p99 is separated lower beside the load"), explained.get(0));
        String scheduling = d.substring(d.indexOf("### 2.7"), d.indexOf("### 2.8"));
        assertTrue(scheduling.contains("Figure 7: release jitter p99 per runtime under each of its profiles (default, noidle)"), scheduling);
    }

    /**
     * Section 2.14 repeats every test of the document on the previous evaluation's data: on the very same data each
     * verdict comes back, so every separated test held and none is missing; the conclusions say so.
     */
    @Test
    void onTheSameDataEveryTestOfTheDocumentHolds() throws Exception {
        Path now = noidleStore("same", 1);
        String d = document(now, "same.db", dir.resolve("same"), new EvaluationDocument.Previous(now, "evaluation/previous.db.gz"));
        Map<String, Integer> outcomes = outcomes(d);
        int held = outcomes.get("separated the same way in both");
        assertTrue(held > 0, "the noidle pairs are separated: " + outcomes);
        assertEquals(held + outcomes.get("separated in neither"), outcomes.values().stream().mapToInt(Integer::intValue).sum(), outcomes.toString());
        List<List<String>> listed = table(d, "The tests separated in either evaluation");
        assertEquals(held, listed.size(), listed.toString());
        assertTrue(listed.stream().allMatch(r -> r.get(4).equals(r.get(5)) && r.get(4).endsWith(", separated")), listed.toString());
        assertTrue(listed.stream().anyMatch(r -> r.subList(0, 4).equals(List.of("native", "native/noidle", "skip, 6400 particles",
                "release jitter p99"))), listed.toString());
        // Figure 14 draws each test's two ratios: here only outcomes of a verdict that came back
        assertTrue(d.contains("*Figure 14: each test's ratio of the means B/A in this evaluation against the previous one"), d);
        String figure = Files.readString(dir.resolve("same/evaluation/reproducibility.svg"));
        assertTrue(figure.contains("separated the same way in both") && figure.contains("the same ratio in both"), "legend");
        assertFalse(figure.contains("evaluation only") || figure.contains("opposite") || figure.contains("nothing to draw"), "legend");
        assertTrue(d.contains("- **From one evaluation to the next**: 0 of the " + held + " tests that either evaluation separated (this "
                + "one or the previous) were not separated the same way by the other (2.14, Figure 14)"), d);
        assertTrue(d.contains("- Reproducibility: of the " + held + " tests separated in this evaluation, the previous one separated "
                + held + " the same way, 0 the opposite way and 0 not at all, and did not run 0; it separated 0 others that this one "
                + "does not (2.14)."), d);
    }

    /**
     * A difference the previous evaluation did not show (native's noidle faster now, not before) is named as not
     * reproduced, both ways round; a configuration the previous evaluation did not run leaves its tests without a
     * verdict there. Without previous data the section says that no test was repeated.
     */
    @Test
    void aDifferenceOnlyOneEvaluationSeparatesIsNamedAsNotReproduced() throws Exception {
        Path now = noidleStore("now", 1);
        FixtureDb f = new FixtureDb();
        f.configs = defaultAndNoidle(1.0);
        f.configs.removeIf(c -> c.id().equals("temurin-25/noidle"));
        f.seed = 2;
        Path before = comparisonStore(f, "before");
        String d = document(now, "now.db", dir.resolve("now"), new EvaluationDocument.Previous(before, "evaluation/previous.db.gz"));
        assertTrue(d.contains("data of the previous evaluation, `evaluation/previous.db.gz` (runs started "), d);
        List<String> jitter = noidleJitterRow(d);
        assertTrue(jitter.get(4).endsWith(", separated") && jitter.get(5).endsWith(", not separated"), jitter.toString());
        assertEquals("separated in this evaluation only", jitter.get(6));
        Map<String, Integer> o = outcomes(d);
        assertTrue(o.get("not in the previous evaluation (a configuration or setting it did not run)") >= 2,
                "temurin-25/noidle's latency and jitter tests: " + o);
        int held = o.get("separated the same way in both");
        int either = held + o.get("separated in this evaluation only") + o.get("separated in the previous evaluation only")
                + o.get("separated the opposite way");
        assertTrue(d.contains("- **From one evaluation to the next**: " + (either - held) + " of the " + either + " tests that "), d);

        String reversed = document(before, "before.db", dir.resolve("reversed"), new EvaluationDocument.Previous(now, "now.db.gz"));
        assertEquals("separated in the previous evaluation only", noidleJitterRow(reversed).get(6));
        assertTrue(reversed.contains("others that this one does not (2.14)."), reversed);

        String alone = document(now, "now.db", dir.resolve("alone"), new EvaluationDocument.Previous(null, "evaluation/previous.db.gz"));
        assertTrue(alone.contains("**No previous evaluation.** There is no earlier evaluation's data at `evaluation/previous.db.gz`"), alone);
        assertFalse(alone.contains("Table 14:") || alone.contains("Figure 14:") || alone.contains("From one evaluation"), alone);
        assertTrue(Files.readString(dir.resolve("now/evaluation/reproducibility.svg")).contains("separated in this evaluation only"));
        assertTrue(alone.contains("- Reproducibility: no previous evaluation to repeat the tests on (2.14)."), alone);
    }

    /** Table 14: how many of the document's tests had each outcome. */
    private static Map<String, Integer> outcomes(String d) {
        Map<String, Integer> out = new java.util.LinkedHashMap<>();
        table(d, "Table 14:").forEach(r -> out.put(r.get(0), Integer.parseInt(r.get(1))));
        return out;
    }

    /** The row of native against native/noidle on release jitter p99 in 2.14's list of separated tests. */
    private static List<String> noidleJitterRow(String d) {
        return table(d, "The tests separated in either evaluation").stream()
                .filter(r -> r.subList(0, 2).equals(List.of("native", "native/noidle")) && r.get(3).equals("release jitter p99"))
                .findFirst().orElseThrow(() -> new AssertionError("no native/noidle jitter row in " + d));
    }

    /** A store of {@link #defaultAndNoidle} where native's noidle releases on time and computes faster. */
    private Path noidleStore(String name, long seed) throws Exception {
        FixtureDb f = new FixtureDb();
        f.configs = defaultAndNoidle(0.8);
        f.jitterScale = Map.of("native/noidle", 0.3);
        f.seed = seed;
        return comparisonStore(f, name);
    }

    /** native and temurin-25, each under its default profile and under noidle; native's noidle at {@code nativeNoidleSpeed}. */
    private static List<FixtureDb.Config> defaultAndNoidle(double nativeNoidleSpeed) {
        return new ArrayList<>(List.of(new FixtureDb.Config("native", "", "gcc 12.2.0", 1.0, "ok"),
                new FixtureDb.Config("native", "noidle", "gcc 12.2.0", nativeNoidleSpeed, "ok"),
                new FixtureDb.Config("temurin-25", "default", "25+36", 1.2, "ok"),
                new FixtureDb.Config("temurin-25", "noidle", "25+36", 1.2, "ok")));
    }

    /** The document of {@code f}'s configurations at one comparison point: skip, 6400 particles, 10 runs a side. */
    private String comparisonDocument(FixtureDb f, String name) throws Exception {
        return document(comparisonStore(f, name), name + ".db", dir.resolve(name));
    }

    /** The store of {@code f}'s configurations at one comparison point: skip, 6400 particles, 10 runs a side. */
    private Path comparisonStore(FixtureDb f, String name) throws Exception {
        f.policies = List.of("skip");
        f.particles = List.of(6400);
        f.repetitions = Separation.MIN_REPETITIONS;
        f.durationS = 6;
        return ReportFixtures.write(f, dir, name + ".db");
    }

    @Test
    void everyIntervalIsWrittenAsTheMethodSaysMeanAndItsBracket() {
        // the method gives `mean [low, high]`, a percentile-bootstrap interval: never a symmetric "±"
        assertTrue(doc.contains("(`mean [low, high]`)"), doc);
        assertFalse(doc.contains("±"), "an interval written as mean ± half-width, which the document does not compute");
        assertTrue(doc.contains("Table 4: the thesis's missCount per run (under skip, the dropped jobs), policy skip (mean [95% CI]"), doc);
    }

    @Test
    void everyFigureIsNumberedAfterTheTableOfItsSection() {
        // the document ran Figure 1, 2a-2d, 2, 3-3h, 6, 6b, 7, 8, 4, 5: the spectrum (Table 3's section) was
        // "Figure 2" after 2a-2d (the completion curves of Table 2's), and the memory and cause figures came
        // after Figure 8; a figure now carries its section's table number, lettered after it
        String heading = null;
        int figures = 0;
        for (String line : doc.lines().toList()) {
            if (line.startsWith("### ")) {
                heading = line;
            }
            Matcher m = Pattern.compile("^\\*Figure (\\w+):").matcher(line);
            if (!m.find()) {
                continue;
            }
            figures++;
            assertTrue(heading != null, line);
            Matcher t = Pattern.compile("\\(Table (\\w+)").matcher(heading);
            assertTrue(t.find(), "a figure in a section of no table: " + heading);
            String figure = m.group(1), table = t.group(1);
            assertTrue(figure.equals(table) || figure.matches(Pattern.quote(table) + "[a-z]"),
                    "Figure " + figure + " in the section of Table " + table + ": " + heading);
        }
        assertTrue(figures >= 10, "figures: " + figures);
    }

    @Test
    void aTableThatWritesNaSaysWhatItMeans() throws Exception {
        // Table 4 said "empty: not run" and wrote n/a, unexplained, for configurations run but never completed;
        // Table 6b said "`-` where no job saw its abort" and wrote n/a there
        FixtureDb f = new FixtureDb();
        f.configs = new ArrayList<>(List.of(new FixtureDb.Config("native", "", "gcc 12.2.0", 1.0, "ok"),
                new FixtureDb.Config("temurin-21", "shenandoah", "21.0.5", 1.1, "unsupported")));
        f.policies = List.of("skip");
        f.particles = List.of(100, 400);
        f.repetitions = 2;
        f.durationS = 6;
        String unsupported = document(ReportFixtures.write(f, dir, "unsupported.db"), "unsupported.db", dir.resolve("unsupported"));
        assertTrue(tablesWithNa(unsupported).contains("Table 4"), "Table 4 of a runtime never completed");
        assertTrue(tablesWithNa(doc).contains("Table 6b"), "Table 6b of runs with no abort latency");
    }

    /** The tables of {@code document} that write n/a, each checked to say in its caption what n/a is. */
    private static List<String> tablesWithNa(String document) {
        List<String> out = new ArrayList<>();
        String[] lines = document.split("\n");
        for (int i = 0; i < lines.length; i++) {
            if (!lines[i].matches("^Table \\w+: .*")) {
                continue;
            }
            StringBuilder text = new StringBuilder(lines[i]);
            int j = i + 1;
            for (; j < lines.length && !lines[j].startsWith("|"); j++) {
                text.append('\n').append(lines[j]);
            }
            boolean na = false;
            for (; j < lines.length && lines[j].startsWith("|"); j++) {
                na |= lines[j].contains("| n/a |");
            }
            if (na) {
                out.add(lines[i].substring(0, lines[i].indexOf(':')));
                assertTrue(text.toString().contains("n/a"), "a table of n/a cells that does not say what n/a is: " + lines[i]);
            }
        }
        return out;
    }

    @Test
    void spectrumAndAbortCaptionsSayWhichJobsTheyCover() {
        // a dropped job has no task latency, and abort latency is over the jobs an abort took hold of, not over all jobs
        assertTrue(doc.contains("*Figure 3: task latency by percentile (every completed job of every repetition"), doc);
        assertTrue(doc.contains("particles (every job an abort took hold of, "), doc);
        assertFalse(doc.contains("all jobs of all repetitions") || doc.contains("every aborted job"), doc);
    }

    @Test
    void aMissCountColumnOverSeveralPoliciesSaysWhatItCountsUnderEach() {
        for (String caption : List.of("Table 2:", "Table 6:")) {
            String header = doc.substring(doc.indexOf(caption)).lines().filter(l -> l.startsWith("|")).findFirst().orElseThrow();
            assertTrue(header.contains("| missCount (skip: dropped; terminate: dropped or aborted; queue: late) |"), header);
        }
    }

    @Test
    void tableCellsFromTheStoreCannotBreakTheTable() {
        assertEquals("a\\|b &lt;script&gt;", EvaluationDocument.escape("a|b <script>"));
    }

    private static StoredRun run(String startedAt, String codeVersion) {
        StoredRun r = new StoredRun();
        r.startedAt = startedAt;
        r.codeVersion = codeVersion;
        return r;
    }

    @Test
    void theHeaderSaysWhichCodeMadeTheRunsOldestFirst() {
        assertEquals("made by more than one version of jmclbench, oldest first: 2 runs by a version not recorded,"
                        + " 1 run by commit 1a2b3c4-dirty, 2 runs by commit 9f8e7d6",
                ConfigurationFacts.codeVersions(List.of(run("2026-11-27T11:00Z", "9f8e7d6"), run("2026-11-27T02:00Z", null),
                        run("2026-11-27T10:00Z", "1a2b3c4-dirty"), run("2026-11-27T12:00Z", "9f8e7d6"), run("2026-11-27T03:00Z", null))));
        assertEquals("every run by jmclbench commit 9f8e7d6", ConfigurationFacts.codeVersions(List.of(run("t", "9f8e7d6"))));
        assertTrue(doc.contains("which jmclbench version made them is not recorded: the store predates that"),
                "the fixture store is schema 2: " + doc.lines().findFirst().orElse(""));
    }
}
