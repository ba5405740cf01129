package org.jmclbench.tooling.runner;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.sql.Connection;
import java.sql.DriverManager;
import java.sql.ResultSet;
import java.sql.Statement;
import java.util.concurrent.TimeUnit;
import java.util.stream.Stream;

import org.jmclbench.tooling.Fixtures;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Two matrices on one store: while the first is mid-run (its fake runtime waits at a gate the test
 * opens), a second matrix or merge into the same store is refused at once, whatever path names it,
 * and writes nothing; a reader is not held up. When the first ends every run is there once.
 */
class ConcurrentMatrixTest {

    @TempDir
    Path dir;

    @Test
    void aSecondWriterIsRefusedAndNoRunIsLostOrDoubled() throws Exception {
        Fixtures.home(dir);
        String gated = Fixtures.fakeJava(dir, "g", "gate", 0, null, 21).toString();
        Path db = dir.resolve("out/results.db");
        String[] matrix = {"matrix", "--java", gated, "--policies", "skip,terminate", "--particles", "100,200",
                "--datasets", "tiny", "--timeout", "600", "--db", db.toString()};
        Path log = dir.resolve("first.log");
        Process first = new ProcessBuilder(Fixtures.childCli(dir, matrix)).redirectErrorStream(true)
                .redirectOutput(log.toFile()).start();
        try {
            Path started = dir.resolve("g/started");
            long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(240); // generous: only a hung child reaches it
            while (!Files.exists(started) && first.isAlive() && System.nanoTime() < deadline) {
                Thread.sleep(100);
            }
            assertTrue(Files.exists(started), "the first matrix never reached its first run: " + Files.readString(log));

            assertRefused(db, Fixtures.cli(matrix));
            Path alias = Files.createSymbolicLink(dir.resolve("alias"), dir.resolve("out"));
            String[] viaAlias = matrix.clone();
            viaAlias[viaAlias.length - 1] = alias.resolve("results.db").toString();
            assertRefused(alias.resolve("results.db"), Fixtures.cli(viaAlias));
            Path other = dir.resolve("other/results.db");
            Fixtures.CliResult o = Fixtures.cli("matrix", "--java", Fixtures.fakeJava(dir, "b", "ok", 0, null, 17).toString(),
                    "--datasets", "tiny", "--particles", "300", "--db", other.toString());
            assertEquals(0, o.exitCode(), o.out() + o.err());
            assertRefused(db, Fixtures.cli("merge", other.toString(), "--into", db.toString()));
            assertEquals(0, count(db, "SELECT count(*) FROM runs"), "nothing recorded by the refused writers");

            Fixtures.CliResult report = Fixtures.cli("report", "--db", db.toString(), "--out", dir.resolve("rep").toString(),
                    "--no-export");
            assertEquals(0, report.exitCode(), "a reader does not wait for the writer: " + report.err());
        } finally {
            Files.createFile(dir.resolve("g/open"));
            assertTrue(first.waitFor(300, TimeUnit.SECONDS), "the first matrix did not finish");
        }
        assertEquals(0, first.exitValue(), Files.readString(log));
        assertEquals(4, count(db, "SELECT count(*) FROM runs"));
        assertEquals(4, count(db, "SELECT count(DISTINCT runtime || policy || particles || repetition) FROM runs"));
        assertEquals(4, count(db, "SELECT sum(status = 'ok') FROM runs"), Files.readString(log));

        // the refused command, run again now that the store is free, finds everything done
        Fixtures.CliResult again = Fixtures.cli(matrix);
        assertEquals(0, again.exitCode(), again.out() + again.err());
        assertTrue(again.out().contains("4 already in") && again.out().contains("0 to run"), again.out());
        assertEquals(4, count(db, "SELECT count(*) FROM runs"));
        try (Stream<Path> runs = Files.list(db.resolveSibling("runs"))) {
            assertEquals(4, runs.filter(Files::isDirectory).count(), "one run folder per run");
        }
    }

    private static void assertRefused(Path db, Fixtures.CliResult r) {
        assertEquals(2, r.exitCode(), r.out() + r.err());
        assertEquals(1, r.err().strip().lines().count(), r.err());
        assertTrue(r.err().contains(db.toString()) && r.err().contains("is writing to it"), r.err());
    }

    private static int count(Path db, String sql) throws Exception {
        try (Connection c = DriverManager.getConnection("jdbc:sqlite:" + db); Statement s = c.createStatement()) {
            s.execute("PRAGMA busy_timeout = 10000");
            try (ResultSet rs = s.executeQuery(sql)) {
                return rs.next() ? rs.getInt(1) : -1;
            }
        }
    }
}
