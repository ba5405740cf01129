package org.jmclbench.tooling.store;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.nio.file.Path;
import java.sql.Connection;
import java.sql.DriverManager;
import java.sql.ResultSet;
import java.sql.Statement;
import java.util.Map;
import java.util.TreeMap;

import org.jmclbench.tooling.Fixtures;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** A store of schema version 1 (before engines) is migrated when opened and merged as it is. */
class StoreMigrationTest {

    @TempDir
    Path dir;

    /** The runs table of version 1, as the runner wrote it. */
    static final String V1_RUNS = """
            CREATE TABLE runs (run_key TEXT PRIMARY KEY, matrix_id TEXT, machine_id TEXT, runtime TEXT, runtime_version TEXT,
              profile TEXT, policy TEXT, particles INTEGER, dataset TEXT, load TEXT, repetition INTEGER,
              status TEXT NOT NULL CHECK (status IN ('ok', 'failed', 'timeout', 'unsupported')),
              exit_code INTEGER, failure TEXT, stderr_tail TEXT, started_at TEXT, ended_at TEXT, wall_s REAL, run_dir TEXT,
              summary_json TEXT, seed INTEGER, command_json TEXT)""";

    /** A version 1 store: native, a JVM run with the allocating style, and a failed one that asked for it. */
    private Path v1Store(String name) throws Exception {
        Path db = dir.resolve(name);
        try (Connection c = DriverManager.getConnection("jdbc:sqlite:" + db); Statement s = c.createStatement()) {
            s.execute("CREATE TABLE machines (machine_id TEXT PRIMARY KEY, hostname TEXT, kernel TEXT, cpu_model TEXT,"
                    + " processors INTEGER, doctor_json TEXT)");
            s.execute("CREATE TABLE matrices (matrix_id TEXT PRIMARY KEY, machine_id TEXT, command TEXT, order_seed INTEGER,"
                    + " started_at TEXT, spec_json TEXT)");
            s.execute(V1_RUNS);
            s.execute("CREATE TABLE metrics (run_key TEXT, task TEXT, metric TEXT, stat TEXT, value REAL,"
                    + " PRIMARY KEY (run_key, task, metric, stat))");
            s.execute("CREATE TABLE histograms (run_key TEXT, task TEXT, metric TEXT, hdr TEXT, PRIMARY KEY (run_key, task, metric))");
            s.execute("CREATE TABLE series (run_key TEXT, name TEXT, json TEXT, PRIMARY KEY (run_key, name))");
            s.execute("INSERT INTO runs (run_key, runtime, status, summary_json, command_json) VALUES"
                    + " ('k-native', 'native', 'ok', '{\"parameters\": {\"memory\": \"preallocated\"}}', '[\"run\"]'),"
                    + " ('k-alloc', 'temurin-25', 'ok', '{\"parameters\": {\"memory\": \"allocating\"}}', '[\"java\",\"--memory\",\"allocating\"]'),"
                    + " ('k-failed', 'temurin-25', 'failed', NULL, '[\"java\",\"run\",\"--memory\",\"allocating\"]'),"
                    + " ('k-plain', 'temurin-17', 'unsupported', NULL, '[]')");
            s.execute("INSERT INTO metrics VALUES ('k-alloc', 'run', 'missCount', 'value', 3)");
            s.execute("PRAGMA user_version = 1");
        }
        return db;
    }

    private static Map<String, String> enginesAndStyles(Path db) throws Exception {
        Map<String, String> out = new TreeMap<>();
        try (Connection c = DriverManager.getConnection("jdbc:sqlite:" + db); Statement s = c.createStatement();
             ResultSet rs = s.executeQuery("SELECT run_key, engine, memory FROM runs")) {
            while (rs.next()) {
                out.put(rs.getString(1), rs.getString(2) + " " + rs.getString(3));
            }
        }
        return out;
    }

    private static final Map<String, String> MIGRATED = Map.of("k-native", "native preallocated", "k-alloc", "javase allocating",
            "k-failed", "javase allocating", "k-plain", "javase preallocated");

    @Test
    void openingMigratesTheRunsInPlace() throws Exception {
        Path db = v1Store("old.db");
        try (RunRecorder store = RunRecorder.open(db, "--db")) {
            assertEquals(4, store.runStatuses().size());
        }
        assertEquals(MIGRATED, enginesAndStyles(db));
        try (Connection c = DriverManager.getConnection("jdbc:sqlite:" + db); Statement s = c.createStatement()) {
            try (ResultSet rs = s.executeQuery("PRAGMA user_version")) {
                assertEquals(3, rs.getInt(1));
            }
            try (ResultSet rs = s.executeQuery("SELECT count(*) FROM runs WHERE code_version IS NULL")) {
                assertEquals(4, rs.getInt(1), "the column exists; which code made the old runs was not kept");
            }
            try (ResultSet rs = s.executeQuery("SELECT count(*) FROM memory_areas")) {
                assertEquals(0, rs.getInt(1), "the table exists, empty: old runs reported no areas");
            }
        }
    }

    @Test
    void aVersion1SourceMergesIntoANewStore() throws Exception {
        Fixtures.home(dir);
        Path old = v1Store("old.db");
        Path into = dir.resolve("new/results.db");
        Fixtures.CliResult r = Fixtures.cli("merge", old.toString(), "--into", into.toString());
        assertEquals(0, r.exitCode(), r.out() + r.err());
        assertEquals(MIGRATED, enginesAndStyles(into));
        try (Connection c = DriverManager.getConnection("jdbc:sqlite:" + into); Statement s = c.createStatement();
             ResultSet rs = s.executeQuery("SELECT value FROM metrics WHERE run_key = 'k-alloc'")) {
            assertEquals(3.0, rs.getDouble(1), "the rows beside the run came along");
        }
        try (Connection c = DriverManager.getConnection("jdbc:sqlite:" + old); Statement s = c.createStatement();
             ResultSet rs = s.executeQuery("PRAGMA user_version")) {
            assertEquals(1, rs.getInt(1), "the source is read, not changed");
        }
    }
}
