package org.jmclbench.tooling.runner;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.sql.Connection;
import java.sql.DriverManager;
import java.sql.ResultSet;
import java.sql.Statement;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import java.util.stream.Stream;

import org.jmclbench.tooling.Fixtures;
import org.sqlite.util.OSInfo;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * A disk that fills, simulated by a file-size limit ({@code ulimit -f}: every write past it fails with
 * "File too large", as one past a full disk fails with "No space left on device"; the JVM and the
 * runtimes under test see it as a failed write). A run that cannot write its folder is that run's
 * failure; a store that cannot grow stops the matrix with one line and keeps every run recorded before;
 * a report that cannot be written fails with one line and leaves the store as it was.
 */
class DiskFullTest {

    @TempDir
    Path dir;

    /** {@code cmd} run with every file it writes limited to {@code kb} KB, those of the temporary folder too. */
    private static List<String> allLimited(int kb, List<String> cmd) {
        List<String> out = new ArrayList<>(List.of("bash", "-c", "ulimit -f " + kb + " && exec \"$@\"", "limited"));
        out.addAll(cmd);
        return out;
    }

    /**
     * {@code cmd} (a JVM's) run with every file it writes limited to {@code kb} KB, SQLite's native library
     * loaded from where the test put it: the disk of the store fills, not the temporary folder.
     */
    private List<String> limited(int kb, List<String> cmd) throws Exception {
        List<String> out = allLimited(kb, cmd);
        Path lib = dir.resolve("sqlite-lib/libsqlitejdbc.so");
        if (!Files.exists(lib)) {
            Files.createDirectories(lib.getParent());
            try (var in = org.sqlite.SQLiteJDBCLoader.class.getResourceAsStream(
                    "/org/sqlite/native/" + OSInfo.getNativeLibFolderPathForCurrentOS() + "/libsqlitejdbc.so")) {
                Files.copy(in, lib);
            }
        }
        out.addAll(5, List.of("-Dorg.sqlite.lib.path=" + lib.getParent(), "-Dorg.sqlite.lib.name=" + lib.getFileName()));
        return out;
    }

    private record Ended(int exitCode, String out, String err) {
    }

    private Ended execute(List<String> cmd, String name) throws Exception {
        Path out = dir.resolve(name + ".out");
        Path err = dir.resolve(name + ".err");
        Process p = new ProcessBuilder(cmd).redirectOutput(out.toFile()).redirectError(err.toFile()).start();
        assertTrue(p.waitFor(300, TimeUnit.SECONDS), name + " did not end");
        return new Ended(p.exitValue(), Files.readString(out), Files.readString(err));
    }

    @Test
    void aStoreThatCannotGrowStopsTheMatrixWithOneLineAndKeepsEveryRunBefore() throws Exception {
        Fixtures.home(dir);
        Path db = dir.resolve("out/results.db");
        String[] matrix = {"matrix", "--java", Fixtures.fakeJava(dir, "a", "ok", 0, null, 21).toString(),
                "--policies", "skip,terminate", "--particles", "100,200,300", "--datasets", "tiny", "--order-seed", "3",
                "--db", db.toString()};
        // the same matrix on an unlimited disk: how large its store grows
        Path full = dir.resolve("full/results.db");
        String[] unlimited = matrix.clone();
        unlimited[unlimited.length - 1] = full.toString();
        assertEquals(0, execute(Fixtures.childCli(dir, unlimited), "unlimited").exitCode());
        int kb = (int) (Files.size(full) / 1024 / 2);

        Ended e = execute(limited(kb, Fixtures.childCli(dir, matrix)), "limited");
        assertEquals(1, e.exitCode(), e.out() + e.err());
        String last = e.err().strip().lines().reduce((a, b) -> b).orElse("");
        assertTrue(last.startsWith("jmclbench: matrix: --db: " + db + ": cannot record ") && last.contains("rerun the same command"),
                e.err());
        assertEquals("ok", single(db, "PRAGMA integrity_check"));
        Map<String, String> before = startedAt(db);
        assertTrue(before.size() > 0 && before.size() < 6, "the disk filled mid-way: " + before.size() + " runs recorded");
        for (String key : before.keySet()) {
            assertTrue(Files.isDirectory(db.resolveSibling("runs").resolve(key)), key + ": a recorded run keeps its folder");
        }

        Ended again = execute(Fixtures.childCli(dir, matrix), "again");
        assertEquals(0, again.exitCode(), again.out() + again.err());
        Map<String, String> after = startedAt(db);
        assertEquals(6, after.size());
        assertEquals("6", single(db, "SELECT count(DISTINCT policy || particles) FROM runs"), "no run twice");
        before.forEach((k, v) -> assertEquals(v, after.get(k), k + ": a run recorded before the disk filled was redone"));
    }

    @Test
    void aStoreOnAFilesystemThatFillsStopsTheMatrixWithTheCause() throws Exception {
        // a real full disk (ENOSPC): a small tmpfs in a mount namespace of its own, where root may make one
        Assumptions.assumeTrue(execute(List.of("unshare", "-m", "bash", "-c", "mount -t tmpfs -o size=64k tmpfs "
                + dir), "can-mount").exitCode() == 0, "no mount namespace here (needs root): the file-size limit stands in");
        Fixtures.home(dir);
        String[] matrix = {"matrix", "--java", Fixtures.fakeJava(dir, "a", "ok", 0, null, 21).toString(),
                "--policies", "skip,terminate", "--particles", "100,200,300", "--datasets", "tiny", "--order-seed", "3",
                "--db", "DB"};
        matrix[matrix.length - 1] = dir.resolve("full/results.db").toString();
        assertEquals(0, execute(Fixtures.childCli(dir, matrix), "unlimited").exitCode());
        long used;
        try (Stream<Path> s = Files.walk(dir.resolve("full"))) {
            used = s.filter(Files::isRegularFile).mapToLong(p -> p.toFile().length()).sum();
        }
        Path mnt = Files.createDirectories(dir.resolve("mnt"));
        Path copy = Files.createDirectories(dir.resolve("copy"));
        matrix[matrix.length - 1] = mnt.resolve("results.db").toString();
        // the store and its run folders on a disk of half what they need; what the disk held is copied out at the end
        List<String> cmd = new ArrayList<>(List.of("unshare", "-m", "bash", "-c", "mount -t tmpfs -o size=" + used / 2 / 1024
                + "k tmpfs '" + mnt + "' || exit 9; \"$@\"; rc=$?; cp -a '" + mnt + "/.' '" + copy + "/'; exit $rc", "full-disk"));
        cmd.addAll(Fixtures.childCli(dir, matrix));
        Ended e = execute(cmd, "full-disk");
        assertEquals(1, e.exitCode(), e.out() + e.err());
        String last = e.err().strip().lines().reduce((a, b) -> b).orElse("");
        assertTrue(last.startsWith("jmclbench: matrix: --db: " + mnt.resolve("results.db") + ": cannot record "), e.err());
        assertTrue(last.contains("full"), "the cause, SQLite's 'database or disk is full', not a failed rollback: " + last);
        Path db = copy.resolve("results.db");
        assertEquals("ok", single(db, "PRAGMA integrity_check"));
        int recorded = startedAt(db).size();
        assertTrue(recorded < 6, recorded + " runs recorded on half the room they need");
    }

    @Test
    void aRunThatCannotWriteItsFolderIsThatRunsFailure() throws Exception {
        Fixtures.home(dir);
        // the C baseline on a disk that takes 2 KB per file: its writes fail (SIGXFSZ ignored, as a JVM does)
        Path repo = Path.of(System.getProperty("user.dir")).toAbsolutePath().getParent();
        Process make = new ProcessBuilder("make", "-s", "-C", repo.resolve("native").toString(), "build/jmclbench-native")
                .redirectErrorStream(true).start();
        String made = new String(make.getInputStream().readAllBytes());
        assertEquals(0, make.waitFor(), "make -C native: " + made);
        Path nat = dir.resolve("small-disk/jmclbench-native");
        Files.createDirectories(nat.getParent());
        Files.writeString(nat, String.join("\n", "#!/usr/bin/env bash",
                "trap '' XFSZ",
                "ulimit -f 2",
                "exec '" + repo.resolve("native/build/jmclbench-native") + "' \"$@\"", ""));
        Files.setPosixFilePermissions(nat, PosixFilePermissions.fromString("rwxr-xr-x"));
        Path db = dir.resolve("out/results.db");
        Ended e = execute(Fixtures.childCli(dir, "matrix", "--native", nat.toString(), "--runtimes", "native",
                "--particles", "100", "--datasets", repo.resolve("data/match-quick").toString(), "--time-scale", "0.1",
                "--db", db.toString()), "small-disk");
        assertEquals(0, e.exitCode(), "a failed run is recorded and the matrix ends normally: " + e.out() + e.err());
        assertTrue(e.out().contains("0 ok, 1 failed"), e.out());
        try (Connection c = DriverManager.getConnection("jdbc:sqlite:" + db); Statement s = c.createStatement();
             ResultSet rs = s.executeQuery("SELECT status, failure, stderr_tail, summary_json FROM runs")) {
            assertTrue(rs.next());
            assertEquals("failed", rs.getString(1));
            String why = rs.getString(2) + "\n" + rs.getString(3);
            assertTrue(why.contains("File too large"), why);
            assertNull(rs.getString(4), "no summary of a run whose folder is incomplete");
            assertFalse(rs.next());
        }
        assertEquals("ok", single(db, "PRAGMA integrity_check"));
    }

    @Test
    void aReportThatCannotBeWrittenFailsWithOneLineAndLeavesTheStore() throws Exception {
        Fixtures.home(dir);
        Path db = dir.resolve("out/results.db");
        Fixtures.CliResult m = Fixtures.cli("matrix", "--java", Fixtures.fakeJava(dir, "a", "ok", 0, null, 21).toString(),
                "--particles", "100,200", "--datasets", "tiny", "--db", db.toString());
        assertEquals(0, m.exitCode(), m.err());
        byte[] store = Files.readAllBytes(db);
        // with the temporary folder full too, SQLite's library cannot be unpacked: the machine's failure, not the file's
        List<String> report = Fixtures.childCli(dir, "report", "--db", db.toString(), "--out", dir.resolve("report").toString());
        Ended noLib = execute(allLimited(8, report), "no-sqlite");
        assertEquals(1, noLib.exitCode(), noLib.err());
        String noLibLast = noLib.err().strip().lines().reduce((a, b) -> b).orElse("");
        assertTrue(noLibLast.startsWith("jmclbench: report: cannot load SQLite's native library"), noLib.err());
        Ended e = execute(limited(8, report), "report");
        assertEquals(1, e.exitCode(), e.out() + e.err());
        String last = e.err().strip().lines().reduce((a, b) -> b).orElse("");
        assertTrue(last.startsWith("jmclbench: report: ") && last.contains("File too large"), e.err());
        assertFalse(e.err().contains("\tat "), "no stack trace: " + e.err());
        assertArrayEquals(store, Files.readAllBytes(db), "the report only reads the store");
    }

    private static Map<String, String> startedAt(Path db) throws Exception {
        return Fixtures.columns(db, "SELECT run_key, started_at FROM runs");
    }

    private static String single(Path db, String sql) throws Exception {
        try (Connection c = DriverManager.getConnection("jdbc:sqlite:" + db); Statement s = c.createStatement();
             ResultSet rs = s.executeQuery(sql)) {
            return rs.next() ? rs.getString(1) : null;
        }
    }
}
