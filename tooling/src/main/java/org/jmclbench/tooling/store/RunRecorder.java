package org.jmclbench.tooling.store;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.sql.Connection;
import java.sql.DriverManager;
import java.sql.PreparedStatement;
import java.sql.ResultSet;
import java.sql.SQLException;
import java.sql.Statement;

import org.jmclbench.tooling.attribution.AttributionStore;
import java.sql.Types;
import java.util.HashMap;
import java.util.Map;

/**
 * The SQLite results store: one file, the raw run folders beside it under {@code runs/}. Every run
 * is written in one transaction once it has ended, so a runner killed mid-run leaves no row for it.
 */
public final class RunRecorder implements AutoCloseable {

    private final Path dbFile;
    private final Connection conn;

    private RunRecorder(Path dbFile, Connection conn) {
        this.dbFile = dbFile;
        this.conn = conn;
    }

    /** Opens (creating when absent) the store at {@code dbFile}. */
    public static RunRecorder open(Path dbFile) throws SQLException, IOException {
        Path abs = dbFile.toAbsolutePath().normalize();
        if (abs.getParent() != null) {
            Files.createDirectories(abs.getParent());
        }
        Connection c = DriverManager.getConnection("jdbc:sqlite:" + abs);
        try (Statement s = c.createStatement()) {
            s.execute("PRAGMA busy_timeout = 10000");
            int version;
            try (ResultSet rs = s.executeQuery("PRAGMA user_version")) {
                version = rs.next() ? rs.getInt(1) : 0;
            }
            if (version > Schema.VERSION) {
                c.close();
                throw new SQLException(abs + ": schema version " + version + " is newer than this tool's (" + Schema.VERSION + ")");
            }
            c.setAutoCommit(false);
            for (String ddl : Schema.CREATE) {
                s.execute(ddl);
            }
            java.util.Set<String> have = new java.util.HashSet<>();
            try (ResultSet rs = s.executeQuery("PRAGMA table_info(runs)")) {
                while (rs.next()) {
                    have.add(rs.getString("name"));
                }
            }
            for (String[] col : Schema.ADDED_RUN_COLUMNS) {
                if (!have.contains(col[0])) {
                    s.execute("ALTER TABLE runs ADD COLUMN " + col[0] + " " + col[1]); // an older store: migrate
                }
            }
            for (String fill : Schema.FILL_ENGINES) {
                s.execute(fill);
            }
            s.execute("PRAGMA user_version = " + Schema.VERSION);
            c.commit();
        } catch (SQLException e) {
            c.close();
            throw e;
        }
        return new RunRecorder(abs, c);
    }

    public Path dbFile() {
        return dbFile;
    }

    /** The folder holding the database; run folders are relative to it. */
    public Path baseDir() {
        return dbFile.getParent();
    }

    /** Where the raw folder of run {@code runKey} goes. */
    public Path runFolder(String runKey) {
        return baseDir().resolve("runs").resolve(runKey);
    }

    Connection connection() {
        return conn;
    }

    /** Inserts or refreshes this machine with its latest doctor report. */
    public void saveMachine(MachineInfo m, String doctorJson) throws SQLException {
        try (PreparedStatement ps = conn.prepareStatement(
                "INSERT OR REPLACE INTO machines (machine_id, hostname, kernel, cpu_model, processors, doctor_json) VALUES (?,?,?,?,?,?)")) {
            ps.setString(1, m.machineId());
            ps.setString(2, m.hostname());
            ps.setString(3, m.kernel());
            ps.setString(4, m.cpuModel());
            ps.setInt(5, m.processors());
            ps.setString(6, doctorJson);
            ps.executeUpdate();
        }
        conn.commit();
    }

    /** Records one invocation of matrix/quick. */
    public void saveMatrix(String matrixId, String machineId, String command, long orderSeed, String startedAt,
                           String specJson) throws SQLException {
        try (PreparedStatement ps = conn.prepareStatement(
                "INSERT INTO matrices (matrix_id, machine_id, command, order_seed, started_at, spec_json) VALUES (?,?,?,?,?,?)")) {
            ps.setString(1, matrixId);
            ps.setString(2, machineId);
            ps.setString(3, command);
            ps.setLong(4, orderSeed);
            ps.setString(5, startedAt);
            ps.setString(6, specJson);
            ps.executeUpdate();
        }
        conn.commit();
    }

    /** The status of every run in the store, by run key. */
    public Map<String, String> runStatuses() throws SQLException {
        Map<String, String> m = new HashMap<>();
        try (Statement s = conn.createStatement(); ResultSet rs = s.executeQuery("SELECT run_key, status FROM runs")) {
            while (rs.next()) {
                m.put(rs.getString(1), rs.getString(2));
            }
        }
        return m;
    }

    /** Writes a run and everything derived from it in one transaction, replacing an earlier row of the same key. */
    public void saveRun(RunRow r, RunDetails data) throws SQLException {
        try {
            deleteRun(r.runKey());
            try (PreparedStatement ps = conn.prepareStatement("INSERT INTO runs (run_key, matrix_id, machine_id, runtime,"
                    + " runtime_version, profile, policy, particles, dataset, load, repetition, status, exit_code, failure,"
                    + " stderr_tail, started_at, ended_at, wall_s, run_dir, summary_json, seed, command_json, engine, memory)"
                    + " VALUES (?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?)")) {
                int i = 1;
                ps.setString(i++, r.runKey());
                ps.setString(i++, r.matrixId());
                ps.setString(i++, r.machineId());
                ps.setString(i++, r.runtime());
                ps.setString(i++, r.runtimeVersion());
                ps.setString(i++, r.profile());
                ps.setString(i++, r.policy());
                ps.setInt(i++, r.particles());
                ps.setString(i++, r.dataset());
                ps.setString(i++, r.load());
                ps.setInt(i++, r.repetition());
                ps.setString(i++, r.status());
                if (r.exitCode() == null) {
                    ps.setNull(i++, Types.INTEGER);
                } else {
                    ps.setInt(i++, r.exitCode());
                }
                ps.setString(i++, r.failure());
                ps.setString(i++, r.stderrTail());
                ps.setString(i++, r.startedAt());
                ps.setString(i++, r.endedAt());
                if (r.wallS() == null) {
                    ps.setNull(i++, Types.REAL);
                } else {
                    ps.setDouble(i++, r.wallS());
                }
                ps.setString(i++, r.runDir());
                ps.setString(i++, r.summaryJson());
                ps.setLong(i++, r.seed());
                ps.setString(i++, r.commandJson());
                ps.setString(i++, r.engine());
                ps.setString(i, r.memory());
                ps.executeUpdate();
            }
            try (PreparedStatement ps = conn.prepareStatement(
                    "INSERT INTO memory_areas (run_key, name, size, peak_bytes, bytes_per_release) VALUES (?,?,?,?,?)")) {
                for (MemoryAreaRow a : data.areas) {
                    ps.setString(1, r.runKey());
                    ps.setString(2, a.name());
                    ps.setObject(3, a.size(), Types.INTEGER);
                    ps.setObject(4, a.peakBytes(), Types.INTEGER);
                    ps.setObject(5, a.bytesPerRelease(), Types.REAL);
                    ps.addBatch();
                }
                ps.executeBatch();
            }
            try (PreparedStatement ps = conn.prepareStatement("INSERT INTO metrics (run_key, task, metric, stat, value) VALUES (?,?,?,?,?)")) {
                for (RunDetails.Metric m : data.metrics) {
                    ps.setString(1, r.runKey());
                    ps.setString(2, m.task());
                    ps.setString(3, m.metric());
                    ps.setString(4, m.stat());
                    ps.setDouble(5, m.value());
                    ps.addBatch();
                }
                ps.executeBatch();
            }
            try (PreparedStatement ps = conn.prepareStatement("INSERT INTO histograms (run_key, task, metric, hdr) VALUES (?,?,?,?)")) {
                for (RunDetails.Hdr h : data.histograms) {
                    ps.setString(1, r.runKey());
                    ps.setString(2, h.task());
                    ps.setString(3, h.metric());
                    ps.setString(4, h.base64());
                    ps.addBatch();
                }
                ps.executeBatch();
            }
            try (PreparedStatement ps = conn.prepareStatement("INSERT INTO series (run_key, name, json) VALUES (?,?,?)")) {
                for (RunDetails.Series s : data.series) {
                    ps.setString(1, r.runKey());
                    ps.setString(2, s.name());
                    ps.setString(3, s.json());
                    ps.addBatch();
                }
                ps.executeBatch();
            }
            AttributionStore.insertRows(conn, r.runKey(), data.attributions);
            conn.commit();
        } catch (SQLException e) {
            conn.rollback();
            throw e;
        }
    }

    private void deleteRun(String runKey) throws SQLException {
        for (String t : Schema.RUN_TABLES) {
            try (PreparedStatement ps = conn.prepareStatement("DELETE FROM " + t + " WHERE run_key = ?")) {
                ps.setString(1, runKey);
                ps.executeUpdate();
            }
        }
    }

    @Override
    public void close() throws SQLException {
        conn.close();
    }
}
