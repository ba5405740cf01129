package org.jmclbench.tooling.runner;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.sql.Connection;
import java.sql.DriverManager;
import java.sql.ResultSet;
import java.sql.Statement;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import java.util.stream.Stream;

import org.jmclbench.tooling.Fixtures;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The runner itself is killed with SIGKILL in the middle of a matrix; rerunning the same command
 * must finish it with every run present exactly once, the runs done before the kill untouched.
 */
class KillResumeTest {

    @TempDir
    Path dir;

    @Test
    void aMatrixKilledMidWayResumesWithEveryRunOnce() throws Exception {
        Fixtures.home(dir);
        Path db = dir.resolve("out/results.db");
        List<String> cmd = Fixtures.childCli(dir,
                "matrix", "--java", Fixtures.fakeJava(dir, "a", "ok", 1.0, null, 17).toString(),
                "--java", Fixtures.fakeJava(dir, "b", "ok", 1.0, null, 21).toString(),
                "--policies", "skip,terminate", "--particles", "100,200,300", "--datasets", "tiny",
                "--db", db.toString());
        Path log1 = dir.resolve("first.log");
        Process first = new ProcessBuilder(cmd).redirectErrorStream(true).redirectOutput(log1.toFile()).start();
        // wait (generously: the machine is shared) until a few runs are committed, then kill -9
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(240);
        Map<String, String> before = new HashMap<>();
        while (before.size() < 4 && System.nanoTime() < deadline && first.isAlive()) {
            Thread.sleep(200);
            before = rows(db);
        }
        assertTrue(first.isAlive(), "the runner ended before it could be killed: " + Files.readString(log1));
        first.destroyForcibly(); // SIGKILL: no shutdown hook runs
        first.waitFor(30, TimeUnit.SECONDS);
        before = rows(db);
        assertTrue(before.size() >= 4 && before.size() < 12, "rows at the kill: " + before.size());

        Process second = new ProcessBuilder(cmd).redirectErrorStream(true).redirectOutput(dir.resolve("second.log").toFile()).start();
        assertTrue(second.waitFor(300, TimeUnit.SECONDS), "the resumed matrix did not finish");
        String log2 = Files.readString(dir.resolve("second.log"));
        assertEquals(0, second.exitValue(), log2);
        assertTrue(log2.contains(before.size() + " already in"), log2);

        Map<String, String> after = rows(db);
        assertEquals(12, after.size(), "2 runtimes x 2 policies x 3 sizes");
        try (Connection c = DriverManager.getConnection("jdbc:sqlite:" + db); Statement s = c.createStatement();
             ResultSet rs = s.executeQuery("SELECT count(*), count(DISTINCT runtime || profile || policy || particles || repetition),"
                     + " sum(status = 'ok') FROM runs")) {
            assertTrue(rs.next());
            assertEquals(12, rs.getInt(1));
            assertEquals(12, rs.getInt(2), "no configuration twice");
            assertEquals(12, rs.getInt(3), "all ok: " + log2);
        }
        for (Map.Entry<String, String> e : before.entrySet()) {
            assertEquals(e.getValue(), after.get(e.getKey()), "a run committed before the kill was redone");
        }
        // one complete run folder per run, no leftovers of the killed run
        for (String key : after.keySet()) {
            try (Stream<Path> s = Files.walk(db.getParent().resolve("runs").resolve(key))) {
                List<Path> leaves = s.filter(p -> p.getFileName().toString().equals("summary.json")).toList();
                assertEquals(1, leaves.size(), key + ": " + leaves);
            }
            try (Stream<Path> s = Files.walk(db.getParent().resolve("runs").resolve(key))) {
                assertTrue(s.noneMatch(p -> p.getFileName().toString().endsWith(".partial")), key);
            }
        }
        assertEquals(12, Files.list(db.getParent().resolve("runs")).count());
    }

    /** run_key -> started_at of every committed run. */
    private static Map<String, String> rows(Path db) {
        Map<String, String> m = new HashMap<>();
        if (!Files.isRegularFile(db)) {
            return m;
        }
        try (Connection c = DriverManager.getConnection("jdbc:sqlite:" + db); Statement s = c.createStatement()) {
            s.execute("PRAGMA busy_timeout = 5000");
            try (ResultSet rs = s.executeQuery("SELECT run_key, started_at FROM runs")) {
                while (rs.next()) {
                    m.put(rs.getString(1), rs.getString(2));
                }
            }
        } catch (java.sql.SQLException e) {
            return m; // the schema may not exist yet
        }
        return m;
    }
}
