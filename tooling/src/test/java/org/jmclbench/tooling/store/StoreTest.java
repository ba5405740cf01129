package org.jmclbench.tooling.store;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.sql.Connection;
import java.sql.DriverManager;
import java.sql.ResultSet;
import java.sql.Statement;
import java.util.ArrayList;
import java.util.List;

import org.HdrHistogram.Histogram;
import org.jmclbench.tooling.Fixtures;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;

/** Merge keeps every run once with its folder; series are down-sampled keeping latency peaks. */
class StoreTest {

    @TempDir
    Path dir;

    private void matrix(Path db, String particles, String... javas) {
        List<String> a = new ArrayList<>(List.of("matrix", "--datasets", "tiny", "--particles", particles, "--db", db.toString()));
        for (String j : javas) {
            a.add("--java");
            a.add(j);
        }
        Fixtures.CliResult r = Fixtures.cli(a.toArray(String[]::new));
        assertEquals(0, r.exitCode(), r.out() + r.err());
    }

    /** A store at {@code name} (below the test's folder) holding fake-17's runs at {@code particles}. */
    private Path storeOfJava17Runs(String name, String particles) throws Exception {
        Fixtures.home(dir);
        Path db = dir.resolve(name);
        matrix(db, particles, Fixtures.FakeJvms.in(dir).java17());
        return db;
    }

    @Test
    void mergeKeepsEveryRunOnceAndCopiesFolders() throws Exception {
        Fixtures.home(dir);
        Fixtures.FakeJvms jvms = Fixtures.FakeJvms.in(dir);
        Path dbA = dir.resolve("A/results.db");
        Path dbB = dir.resolve("B/results.db");
        matrix(dbA, "100,200", jvms.java17(), jvms.crashing11()); // fake-17 x2, fake-11 x2 (failed)
        matrix(dbB, "200,300", jvms.java17(), jvms.java21());     // fake-17 200 overlaps A's; fake-21 x2
        Path dbC = dir.resolve("C/results.db");
        Fixtures.CliResult r = Fixtures.cli("merge", dbA.toString(), dbB.toString(), "--into", dbC.toString());
        assertEquals(0, r.exitCode(), r.err());
        // fake-17 at 200 particles was measured in both: B's run is another measurement, left out, not "already in"
        assertTrue(r.out().contains("B/results.db: 3 runs merged, 0 already in " + dbC + ", 1 left out: " + dbC
                + " holds another measurement under the same run key"), r.out());
        try (Connection c = DriverManager.getConnection("jdbc:sqlite:" + dbC); Statement s = c.createStatement()) {
            try (ResultSet rs = s.executeQuery("SELECT count(*), count(DISTINCT run_key), sum(status='ok') FROM runs")) {
                rs.next();
                assertEquals(7, rs.getInt(1));
                assertEquals(7, rs.getInt(2));
                assertEquals(5, rs.getInt(3));
            }
            try (ResultSet rs = s.executeQuery("SELECT count(*) FROM (SELECT DISTINCT run_key FROM metrics)")) {
                rs.next();
                assertEquals(5, rs.getInt(1), "metrics of every ok run came along");
            }
            try (ResultSet rs = s.executeQuery("SELECT count(*), count(DISTINCT run_key), min(name), max(engine) FROM memory_areas"
                    + " JOIN runs USING (run_key)")) {
                rs.next();
                assertEquals(5, rs.getInt(1), "the memory area of every ok run came along");
                assertEquals(5, rs.getInt(2));
                assertEquals("heap", rs.getString(3));
                assertEquals("javase", rs.getString(4));
            }
            try (ResultSet rs = s.executeQuery("SELECT run_dir FROM runs WHERE status = 'ok'")) {
                while (rs.next()) {
                    assertTrue(Files.isRegularFile(dbC.getParent().resolve(rs.getString(1)).resolve("summary.json")), rs.getString(1));
                }
            }
            try (ResultSet rs = s.executeQuery("SELECT count(*) FROM matrices")) {
                rs.next();
                assertEquals(2, rs.getInt(1));
            }
        }
        // merging again changes nothing
        Fixtures.CliResult again = Fixtures.cli("merge", dbA.toString(), dbB.toString(), "--into", dbC.toString());
        assertTrue(again.out().contains("0 runs merged, 4 already in " + dbC + "\n"), again.out());
        assertEquals(2, Fixtures.cli("merge", dir.resolve("nope.db").toString(), "--into", dbC.toString()).exitCode());
        Path notDb = dir.resolve("not.db");
        Files.writeString(notDb, "hello");
        Path dbD = dir.resolve("D/results.db");
        Fixtures.CliResult rejected = Fixtures.cli("merge", dbA.toString(), notDb.toString(), "--into", dbD.toString());
        assertEquals(2, rejected.exitCode(), rejected.err());
        assertTrue(rejected.err().strip().startsWith("jmclbench: " + notDb + ": not a jmclbench results store"), rejected.err());
        assertTrue(!Files.exists(dbD), "nothing is merged when a source is bad");
    }

    @Test
    void twoStoresInOneFolderNeverOverwriteEachOthersRunFolders() throws Exception {
        // results.db and evaluation.db side by side (quick's and evaluate's defaults), one configuration in
        // both: one run key, which named one folder, runs/<key>, that the second store's run overwrote
        Path first = storeOfJava17Runs("results/results.db", "100");
        Path second = storeOfJava17Runs("results/evaluation.db", "100");
        assertEquals(column(first, "SELECT run_key FROM runs"), column(second, "SELECT run_key FROM runs"));
        assertEquals("runs", column(first, "SELECT run_dir FROM runs").get(0).split("/")[0]);
        assertEquals("runs-evaluation", column(second, "SELECT run_dir FROM runs").get(0).split("/")[0]);
        assertRunFoldersHoldTheirSummaries(first);
        assertRunFoldersHoldTheirSummaries(second);
        // merged elsewhere, the second store's runs come from its own folder and land in the target's runs/
        Path merged = dir.resolve("merged/results.db");
        assertEquals(0, Fixtures.cli("merge", second.toString(), "--into", merged.toString()).exitCode());
        assertEquals("runs", column(merged, "SELECT run_dir FROM runs").get(0).split("/")[0]);
        assertRunFoldersHoldTheirSummaries(merged);
    }

    /** Every ok run's run_dir holds the summary.json the store has for it. */
    private static void assertRunFoldersHoldTheirSummaries(Path db) throws Exception {
        try (Connection c = DriverManager.getConnection("jdbc:sqlite:" + db); Statement s = c.createStatement();
             ResultSet rs = s.executeQuery("SELECT run_dir, summary_json FROM runs WHERE status = 'ok'")) {
            int n = 0;
            while (rs.next()) {
                Path summary = db.getParent().resolve(rs.getString(1)).resolve("summary.json");
                assertEquals(rs.getString(2), Files.readString(summary), db + ": " + summary);
                n++;
            }
            assertTrue(n > 0, db + " has ok runs");
        }
    }

    @Test
    void mergingAStoreIntoItselfByAnotherNameChangesNothing() throws Exception {
        Path db = storeOfJava17Runs("A/results.db", "100");
        Path link = Files.createSymbolicLink(dir.resolve("link.db"), db);
        Fixtures.CliResult r = Fixtures.cli("merge", link.toString(), "--into", db.toString());
        assertEquals(0, r.exitCode(), r.err());
        assertTrue(r.out().contains("0 runs merged, 1 already in"), r.out());
        assertEquals(1, column(db, "SELECT run_key FROM runs").size());
    }

    @Test
    void aMergeThatFailsLeavesTheTargetsRunFoldersAsTheyWere() throws Exception {
        Path src = storeOfJava17Runs("S/results.db", "100,200");
        List<String> keys = column(src, "SELECT run_key FROM runs ORDER BY rowid");
        // the target: the first run failed there (its folder holds its own log), the second not there at all
        Path into = dir.resolve("T/results.db");
        Files.createDirectories(into.getParent());
        Files.copy(src, into);
        try (Connection c = DriverManager.getConnection("jdbc:sqlite:" + into); Statement s = c.createStatement()) {
            s.executeUpdate("UPDATE runs SET status = 'failed' WHERE run_key = '" + keys.get(0) + "'");
            s.executeUpdate("DELETE FROM runs WHERE run_key = '" + keys.get(1) + "'");
        }
        Path failedFolder = into.getParent().resolve("runs").resolve(keys.get(0));
        Files.createDirectories(failedFolder);
        Files.writeString(failedFolder.resolve("stderr.txt"), "the target's failed run");
        // the source's second folder cannot be copied (a link to nothing): the merge fails after the first run
        Files.createSymbolicLink(src.getParent().resolve("runs").resolve(keys.get(1)).resolve("broken"), dir.resolve("nothing"));
        Fixtures.CliResult r = Fixtures.cli("merge", src.toString(), "--into", into.toString());
        assertTrue(r.exitCode() != 0, r.out());
        assertTrue(r.err().contains("cannot copy the run folder") && r.err().contains("NoSuchFileException"), r.err());
        assertEquals(List.of("failed"), column(into, "SELECT status FROM runs WHERE run_key = '" + keys.get(0) + "'"),
                "the rows are rolled back");
        assertEquals(List.of("stderr.txt"), Files.list(failedFolder).map(p -> p.getFileName().toString()).toList(),
                "the failed run's folder is still its own");
        assertTrue(!Files.exists(into.getParent().resolve("runs").resolve(keys.get(1))), "no folder without its row");
    }

    @Test
    void latencySeriesKeepsPeaksWhenDownSampled() throws Exception {
        List<RunFolderIngest.Job> jobs = new ArrayList<>();
        for (int i = 0; i < 5000; i++) {
            long lat = i == 3333 ? 99_000_000 : 1_000_000 + i;
            jobs.add(new RunFolderIngest.Job(i, i * 50_000_000L, i * 50_000_000L + 1000, i * 50_000_000L + 1000 + lat,
                    i * 50_000_000L + 50_000_000L, "done", lat, -1));
        }
        JsonNode s = new ObjectMapper().readTree(RunFolderIngest.latencySeries(jobs));
        assertTrue(s.get("rows").size() <= RunFolderIngest.MAX_SERIES_ROWS);
        boolean peak = false;
        for (JsonNode row : s.get("rows")) {
            peak |= row.get(2).asLong() == 99_000_000;
        }
        assertTrue(peak, "the slowest job survives down-sampling");
        List<double[]> rows = new ArrayList<>();
        for (int i = 0; i < 4501; i++) {
            rows.add(new double[] {i});
        }
        List<double[]> kept = RunFolderIngest.strided(rows);
        assertTrue(kept.size() <= RunFolderIngest.MAX_SERIES_ROWS, "" + kept.size());
        assertEquals(4500, kept.get(kept.size() - 1)[0]);
    }

    @Test
    void abortLatencyIsIngestedFromTheAbortColumnAndOldJobFilesStillRead() throws Exception {
        Files.writeString(dir.resolve("odoData.txt"), "# index release_ns start_ns end_ns deadline_ns outcome cpu_ns abort_ns\n"
                + "0 0 100 900 50000000 terminated -1 400\n1 50000000 50000100 50000900 100000000 done -1 -1\n");
        // laserData.txt as written before the abort column
        Files.writeString(dir.resolve("laserData.txt"), "# index release_ns start_ns end_ns deadline_ns outcome cpu_ns\n"
                + "0 70000000 70000100 70000900 120000000 done -1\n");
        JsonNode summary = new ObjectMapper().readTree("{\"tasks\": {\"predict\": {\"abortsCompleted\": 0, "
                + "\"abortLatencyNs\": {\"count\": 1, \"p50\": 500, \"max\": 500}}}}");
        RunDetails d = RunFolderIngest.ingest(dir, summary, null);
        List<RunDetails.Hdr> aborts = d.histograms.stream().filter(h -> h.metric().equals("abortLatencyNs")).toList();
        assertEquals(List.of("predict", "all"), aborts.stream().map(RunDetails.Hdr::task).toList(), "no abort in update");
        Histogram h = RunFolderIngest.decode(aborts.get(0).base64());
        assertEquals(1, h.getTotalCount());
        assertEquals(500, h.getMaxValue(), 1, "end 900 - abort 400");
        assertTrue(d.metrics.contains(new RunDetails.Metric("predict", "abortLatencyNs", "p50", 500)), d.metrics.toString());
        assertTrue(d.metrics.contains(new RunDetails.Metric("predict", "abortsCompleted", "value", 0)), d.metrics.toString());
    }

    @Test
    void theDeadlineAccountingIsFlattenedAndAnInfiniteQuantileStaysInTheSummary() throws Exception {
        JsonNode summary = new ObjectMapper().readTree("{\"tasks\": {\"update\": {\"released\": 40, \"deadlineMisses\": 3,"
                + " \"missRatio\": 0.075, \"responseTimeReleasedNs\": {\"count\": 40, \"completed\": 37, \"p50\": 2000000,"
                + " \"p99\": \"inf\", \"max\": \"inf\"}}}}");
        RunDetails d = new RunDetails();
        RunFolderIngest.flattenSummary(summary, d);
        java.util.Map<String, Double> rows = new java.util.HashMap<>();
        d.metrics.forEach(m -> rows.put(m.task() + "/" + m.metric() + "/" + m.stat(), m.value()));
        assertEquals(3.0, rows.get("update/deadlineMisses/value"));
        assertEquals(0.075, rows.get("update/missRatio/value"));
        assertEquals(2000000.0, rows.get("update/responseTimeReleasedNs/p50"));
        assertTrue(!rows.containsKey("update/responseTimeReleasedNs/p99"), "\"inf\" is no number: the report reads it from the summary");
    }

    @Test
    void histogramsRoundTrip() {
        Histogram h = new Histogram(3);
        for (int i = 1; i <= 1000; i++) {
            h.recordValue(i * 1000L);
        }
        Histogram back = RunFolderIngest.decode(RunFolderIngest.encode(h));
        assertEquals(1000, back.getTotalCount());
        assertEquals(h.getValueAtPercentile(99), back.getValueAtPercentile(99));
    }

    /** The first column of {@code query}'s rows in the store {@code db}. */
    private static List<String> column(Path db, String query) throws Exception {
        List<String> values = new ArrayList<>();
        try (Connection c = DriverManager.getConnection("jdbc:sqlite:" + db); Statement s = c.createStatement();
                ResultSet rs = s.executeQuery(query)) {
            while (rs.next()) {
                values.add(rs.getString(1));
            }
        }
        return values;
    }
}
