package org.jmclbench.tooling.attribution;

import java.sql.Connection;
import java.sql.PreparedStatement;
import java.sql.SQLException;
import java.sql.Statement;

/**
 * Writes a run's {@link AttributionData} into the results store (docs/FORMATS.md section 5),
 * inside the caller's transaction: the {@code attributions} table (created here if missing),
 * {@code metrics} rows and the {@code pauses} series.
 */
public final class AttributionStore {
    /** The table this part of the tooling adds to the store. */
    public static final String SCHEMA = """
            CREATE TABLE IF NOT EXISTS attributions (
              run_key TEXT, task TEXT, job_index INTEGER,
              outcome TEXT,
              causes_json TEXT,
              PRIMARY KEY (run_key, task, job_index)
            )""";

    private AttributionStore() {
    }

    /** Inserts {@code attributions} rows (the table must exist: {@link #SCHEMA}). */
    public static void insertRows(Connection conn, String runKey, java.util.List<AttributionData.Row> rows) throws SQLException {
        insertBatch(conn, "INSERT INTO attributions (run_key, task, job_index, outcome, causes_json) VALUES (?,?,?,?,?)",
                rows, (ps, r) -> {
                    ps.setString(1, runKey);
                    ps.setString(2, r.task());
                    ps.setInt(3, r.jobIndex());
                    ps.setString(4, r.outcome());
                    ps.setString(5, r.causesJson());
                });
    }

    /** How one item fills the parameters of an INSERT. */
    private interface RowBinder<T> {
        void bind(PreparedStatement ps, T item) throws SQLException;
    }

    /** Inserts one row per item of {@code items} with {@code sql}, as one batch. */
    private static <T> void insertBatch(Connection conn, String sql, Iterable<T> items, RowBinder<T> binder)
            throws SQLException {
        try (PreparedStatement ps = conn.prepareStatement(sql)) {
            for (T item : items) {
                binder.bind(ps, item);
                ps.addBatch();
            }
            ps.executeBatch();
        }
    }

    /** Creates the {@code attributions} table when the store has none. */
    public static void createSchema(Connection conn) throws SQLException {
        try (Statement s = conn.createStatement()) {
            s.execute(SCHEMA);
        }
    }

    /** Inserts the run's attribution rows, metrics and pause series. */
    public static void write(Connection conn, String runKey, AttributionData data) throws SQLException {
        createSchema(conn);
        insertRows(conn, runKey, data.rows());
        insertBatch(conn, "INSERT INTO metrics (run_key, task, metric, stat, value) VALUES (?,?,?,?,?)",
                data.metrics().stream().filter(m -> Double.isFinite(m.value())).toList(), (ps, m) -> {
                    ps.setString(1, runKey);
                    ps.setString(2, m.task());
                    ps.setString(3, m.metric());
                    ps.setString(4, m.stat());
                    ps.setDouble(5, m.value());
                });
        try (PreparedStatement ps = conn.prepareStatement("INSERT INTO series (run_key, name, json) VALUES (?,?,?)")) {
            ps.setString(1, runKey);
            ps.setString(2, "pauses");
            ps.setString(3, data.pauses());
            ps.executeUpdate();
        }
    }
}
