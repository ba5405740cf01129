package org.jmclbench.tooling.store;

import java.io.IOException;
import java.nio.file.FileAlreadyExistsException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.sql.Connection;
import java.sql.PreparedStatement;
import java.sql.ResultSet;
import java.sql.SQLException;
import java.sql.Statement;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.function.Function;

import org.jmclbench.tooling.attribution.AttributionStore;
import org.jmclbench.tooling.cli.BadUsageException;

/**
 * Writes runs into a results database ({@link ResultsDatabase#openToWrite}): one file, the raw run
 * folders beside it under {@code runs/} (or {@code runs-<name>/} for a second store in the folder,
 * {@link #claimRunsFolder}). Every run is written in one transaction once it has ended,
 * so a runner killed mid-run leaves no row for it, and a write that fails (a full disk) leaves the
 * rows before it as they were.
 */
public final class RunRecorder implements AutoCloseable {

    /** The run folders' folder of the first store to write in a folder. */
    static final String RUNS = "runs";
    /** In {@link #RUNS}, the file naming that store, so that a second store in the folder keeps its runs apart. */
    static final String OWNER = "STORE";

    private final ResultsDatabase db;
    private final Connection conn;
    /** {@link #RUNS}, or {@code runs-<store name>} for a store beside the one that owns {@code runs/}. */
    private final String runsFolder;

    private RunRecorder(ResultsDatabase db, String runsFolder) {
        this.db = db;
        this.conn = db.connection();
        this.runsFolder = runsFolder;
    }

    /**
     * Opens (creating when absent) the store at {@code dbFile} to write, holding its lock until closed.
     *
     * @param option the option that named the file, for messages ({@code --db}); null when positional
     * @throws org.jmclbench.tooling.cli.BadUsageException when the file is not a store this tool writes
     */
    public static RunRecorder open(Path dbFile, String option) {
        boolean existed = Files.exists(dbFile);
        ResultsDatabase db = ResultsDatabase.openToWrite(dbFile, option);
        try {
            return new RunRecorder(db, claimRunsFolder(db.baseDir(), db.file().getFileName().toString()));
        } catch (IOException e) {
            try {
                db.close();
                if (!existed) {
                    Files.deleteIfExists(db.file()); // the store this refusal made would stay, empty, as if it had been used
                }
            } catch (SQLException | IOException ignored) {
                // the refusal below is what the user needs to see
            }
            throw new BadUsageException((option == null ? "" : option + ": ") + dbFile + ": cannot write its run folders in "
                    + db.baseDir() + " (" + e.getClass().getSimpleName() + " " + e.getMessage() + ")");
        }
    }

    /**
     * The folder, below {@code base}, for the run folders of the store named {@code store}. A run
     * folder is named by its run key alone, and two stores in one folder (results.db and
     * evaluation.db) can hold one key: the first to write owns {@code runs/}, any other gets
     * {@code runs-<its name>/}, so that neither overwrites the other's runs. An owner whose file is
     * gone leaves {@code runs/} to the next store.
     */
    static String claimRunsFolder(Path base, String store) throws IOException {
        Path owner = base.resolve(RUNS).resolve(OWNER);
        Files.createDirectories(owner.getParent());
        try {
            Files.writeString(owner, store + "\n", StandardOpenOption.CREATE_NEW); // atomic: one claimant wins
            return RUNS;
        } catch (FileAlreadyExistsException taken) {
            String holder = Files.readString(owner).strip();
            if (holder.equals(store) || !Files.isRegularFile(base.resolve(holder))) {
                Files.writeString(owner, store + "\n");
                return RUNS;
            }
            return RUNS + "-" + (store.endsWith(".db") ? store.substring(0, store.length() - 3) : store);
        }
    }

    public Path dbFile() {
        return db.file();
    }

    /** The folder holding the database; run folders are relative to it. */
    public Path baseDir() {
        return db.baseDir();
    }

    /** Where the raw folder of run {@code runKey} goes. */
    public Path runFolder(String runKey) {
        return baseDir().resolve(runsFolder).resolve(runKey);
    }

    Connection connection() {
        return conn;
    }

    /** Inserts or refreshes this machine with its latest doctor report. */
    public void saveMachine(MachineInfo m, String doctorJson) throws SQLException {
        inTransaction(() -> batch("INSERT OR REPLACE INTO machines (machine_id, hostname, kernel, cpu_model, processors,"
                + " doctor_json) VALUES (?,?,?,?,?,?)", List.of(m), x -> new Object[] {x.machineId(), x.hostname(), x.kernel(),
                x.cpuModel(), x.processors(), doctorJson}));
    }

    /** Records one invocation of matrix/quick. */
    public void saveMatrix(String matrixId, String machineId, String command, long orderSeed, String startedAt,
                           String specJson) throws SQLException {
        Object[] row = {matrixId, machineId, command, orderSeed, startedAt, specJson};
        inTransaction(() -> batch("INSERT INTO matrices (matrix_id, machine_id, command, order_seed, started_at, spec_json)"
                + " VALUES (?,?,?,?,?,?)", List.<Object[]>of(row), x -> x));
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

    /**
     * Writes a run and everything derived from it in one transaction, replacing an earlier row of the
     * same key; when any write fails the transaction is rolled back and the store is as it was.
     */
    public void saveRun(RunRow r, RunDetails data) throws SQLException {
        String key = r.runKey();
        inTransaction(() -> {
            for (String t : Schema.RUN_TABLES) {
                batch("DELETE FROM " + t + " WHERE run_key = ?", List.of(key), k -> new Object[] {k});
            }
            batch("INSERT INTO runs (run_key, matrix_id, machine_id, runtime, runtime_version, profile, policy, particles,"
                    + " dataset, load, repetition, status, exit_code, failure, stderr_tail, started_at, ended_at, wall_s, run_dir,"
                    + " summary_json, seed, command_json, engine, memory, code_version) VALUES (?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?)",
                    List.of(r), x -> new Object[] {x.runKey(), x.matrixId(), x.machineId(), x.runtime(), x.runtimeVersion(),
                        x.profile(), x.policy(), x.particles(), x.dataset(), x.load(), x.repetition(), x.status(), x.exitCode(),
                        x.failure(), x.stderrTail(), x.startedAt(), x.endedAt(), x.wallS(), x.runDir(), x.summaryJson(), x.seed(),
                        x.commandJson(), x.engine(), x.memory(), x.codeVersion()});
            batch("INSERT INTO memory_areas (run_key, name, size, peak_bytes, bytes_per_release) VALUES (?,?,?,?,?)",
                    data.areas, a -> new Object[] {key, a.name(), a.size(), a.peakBytes(), a.bytesPerRelease()});
            batch("INSERT INTO metrics (run_key, task, metric, stat, value) VALUES (?,?,?,?,?)",
                    data.metrics, m -> new Object[] {key, m.task(), m.metric(), m.stat(), m.value()});
            batch("INSERT INTO histograms (run_key, task, metric, hdr) VALUES (?,?,?,?)",
                    data.histograms, h -> new Object[] {key, h.task(), h.metric(), h.base64()});
            batch("INSERT INTO series (run_key, name, json) VALUES (?,?,?)",
                    data.series, x -> new Object[] {key, x.name(), x.json()});
            AttributionStore.insertRows(conn, key, data.attributions);
        });
    }

    /** Statements of one transaction. */
    private interface Work {
        void run() throws SQLException;
    }

    /** Runs {@code work} and commits, or rolls it all back when any of it fails. */
    private void inTransaction(Work work) throws SQLException {
        try {
            work.run();
            conn.commit();
        } catch (SQLException | RuntimeException e) {
            ResultsDatabase.rollBack(conn, e);
            throw e;
        }
    }

    /** Executes {@code sql} once per row, with the row's parameters in order (null for NULL), as one batch. */
    private <T> void batch(String sql, List<T> rows, Function<T, Object[]> params) throws SQLException {
        if (rows.isEmpty()) {
            return;
        }
        try (PreparedStatement ps = conn.prepareStatement(sql)) {
            for (T row : rows) {
                Object[] p = params.apply(row);
                for (int i = 0; i < p.length; i++) {
                    ps.setObject(i + 1, p[i]);
                }
                ps.addBatch();
            }
            ps.executeBatch();
        }
    }

    @Override
    public void close() throws SQLException {
        db.close();
    }
}
