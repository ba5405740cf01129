package org.jmclbench.tooling.store;


import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.file.Path;
import java.sql.Connection;
import java.sql.PreparedStatement;
import java.sql.ResultSet;
import java.sql.SQLException;
import java.sql.Statement;
import java.util.ArrayList;
import java.util.Base64;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.zip.DataFormatException;

import org.HdrHistogram.Histogram;
import org.jmclbench.tooling.cli.BadUsageException;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.MissingNode;

/**
 * Read-only view of the results database (docs/FORMATS.md section 5) for the report and
 * compare: runs, their flattened metrics, histograms, series and the machines.
 */
public final class StoredRuns implements AutoCloseable {

    private final Path file;
    private final ResultsDatabase database;
    private final Connection conn;

    private StoredRuns(Path file, ResultsDatabase database) {
        this.file = file;
        this.database = database;
        this.conn = database.connection();
    }

    /**
     * Opens {@code file} read-only ({@link ResultsDatabase#openToRead}); a missing, foreign, corrupt or
     * newer database is bad input.
     */
    public static StoredRuns open(Path file, String option) throws BadUsageException {
        return new StoredRuns(file, ResultsDatabase.openToRead(file, option));
    }

    public Path file() {
        return file;
    }

    /** One row of {@code machines}. */
    public record Machine(String machineId, String hostname, String kernel, String cpuModel, Integer processors,
                          String doctorJson) {
    }

    /** Every run, in a stable order (configuration, then repetition), with its metrics. */
    public List<StoredRun> runs() {
        Map<String, StoredRun> byKey = new LinkedHashMap<>();
        boolean engineColumns = hasColumn("runs", "engine") && hasColumn("runs", "memory");
        String sql = "SELECT run_key, matrix_id, machine_id, runtime, runtime_version, profile, policy, particles, dataset, load,"
                + " repetition, status, exit_code, failure, stderr_tail, started_at, wall_s, run_dir, summary_json,"
                + (engineColumns ? " engine, memory" : " NULL, NULL")
                + (hasColumn("runs", "code_version") ? ", code_version" : ", NULL") + " FROM runs"
                + " ORDER BY dataset, policy, particles, runtime, profile, 20, 21, repetition, started_at, run_key";
        Map<String, JsonNode> specs = matrixSpecs();
        try (Statement st = conn.createStatement(); ResultSet rs = st.executeQuery(sql)) {
            while (rs.next()) {
                StoredRun r = new StoredRun();
                r.runKey = rs.getString(1);
                r.matrixId = rs.getString(2);
                r.machineId = rs.getString(3);
                r.runtime = nz(rs.getString(4), "?");
                r.runtimeVersion = rs.getString(5);
                r.profile = nz(rs.getString(6), "");
                r.policy = nz(rs.getString(7), "?");
                r.particles = rs.getInt(8);
                r.dataset = nz(rs.getString(9), "?");
                r.load = rs.getString(10);
                r.repetition = rs.getInt(11);
                r.status = nz(rs.getString(12), "?");
                int exit = rs.getInt(13);
                r.exitCode = rs.wasNull() ? null : exit;
                r.failure = rs.getString(14);
                r.stderrTail = rs.getString(15);
                r.startedAt = rs.getString(16);
                double wall = rs.getDouble(17);
                r.wallS = rs.wasNull() ? null : wall;
                r.runDir = rs.getString(18);
                r.summaryJson = rs.getString(19);
                r.engine = rs.getString(20);
                r.memory = rs.getString(21);
                r.codeVersion = rs.getString(22);
                if (r.engine == null || r.memory == null) {
                    // a store before engines: what the summary says, else the Java SE engine (native for C)
                    com.fasterxml.jackson.databind.JsonNode p = r.summary().path("parameters");
                    if (r.engine == null) {
                        r.engine = engineOf(p, "native".equals(r.runtime) ? "native" : "javase");
                    }
                    if (r.memory == null) {
                        r.memory = p.path("memory").asText("preallocated");
                    }
                }
                settings(r, specs.get(r.matrixId));
                byKey.put(r.runKey, r);
            }
            if (hasTable("metrics")) {
                try (ResultSet m = st.executeQuery("SELECT run_key, task, metric, stat, value FROM metrics WHERE value IS NOT NULL")) {
                    while (m.next()) {
                        StoredRun r = byKey.get(m.getString(1));
                        if (r != null) {
                            r.metrics.put(m.getString(2) + "/" + m.getString(3) + "/" + m.getString(4), m.getDouble(5));
                        }
                    }
                }
            }
            if (hasTable("memory_areas")) {
                try (ResultSet a = st.executeQuery("SELECT run_key, name, size, peak_bytes, bytes_per_release FROM memory_areas"
                        + " ORDER BY run_key, rowid")) {
                    while (a.next()) {
                        StoredRun r = byKey.get(a.getString(1));
                        if (r != null) {
                            r.areas.add(new MemoryAreaRow(a.getString(2), (Long) nullable(a, 3, true), (Long) nullable(a, 4, true),
                                    (Double) nullable(a, 5, false)));
                        }
                    }
                }
            }
        } catch (SQLException e) {
            throw new IllegalStateException(file + ": " + ResultsDatabase.oneLine(e.getMessage()), e);
        }
        List<StoredRun> out = new ArrayList<>(byKey.values());
        StoredRun.labelEngines(out);
        return out;
    }

    /** Each matrix's spec_json by matrix id (a spec that is not JSON left out: its runs' settings are not told). */
    private Map<String, JsonNode> matrixSpecs() {
        Map<String, JsonNode> out = new HashMap<>();
        try (Statement st = conn.createStatement(); ResultSet rs = st.executeQuery("SELECT matrix_id, spec_json FROM matrices")) {
            while (rs.next()) {
                try {
                    if (rs.getString(1) != null && rs.getString(2) != null) {
                        out.put(rs.getString(1), SPEC_JSON.readTree(rs.getString(2)));
                    }
                } catch (IOException e) {
                    // unreadable: the settings come from the runs' summaries where they have them
                }
            }
        } catch (SQLException e) {
            throw new IllegalStateException(file + ": " + ResultsDatabase.oneLine(e.getMessage()), e);
        }
        return out;
    }

    private static final ObjectMapper SPEC_JSON = new ObjectMapper();

    /**
     * The run-key settings of {@code r} the columns lack ({@link StoredRun#timeScale} and the others, the
     * alloc load's rates of an allocating scenario), from
     * the spec of the matrix that ran it, which holds them for failed runs too; the time scale, failing
     * that, from the run's summary. Two datasets of one label in one matrix are told apart by the path
     * the summary names.
     */
    private static void settings(StoredRun r, JsonNode spec) {
        JsonNode s = spec == null ? MissingNode.getInstance() : spec;
        JsonNode p = r.summary().path("parameters");
        r.timeScale = s.path("timeScale").isNumber() ? Double.valueOf(s.path("timeScale").asDouble())
                : p.path("timeScale").isNumber() ? Double.valueOf(p.path("timeScale").asDouble()) : null;
        if (s.path("workloadArgs").isArray()) {
            List<String> args = new ArrayList<>();
            s.path("workloadArgs").forEach(a -> args.add(a.asText()));
            r.workloadArgs = String.join(" ", args);
        }
        List<JsonNode> datasets = new ArrayList<>();
        s.path("datasets").forEach(d -> {
            if (r.dataset.equals(d.path("label").asText()) && d.path("digest").isTextual()) {
                datasets.add(d);
            }
        });
        if (datasets.size() > 1) {
            String path = p.at("/dataset/path").asText("");
            datasets.removeIf(d -> !d.path("path").asText().equals(path));
        }
        r.datasetDigest = datasets.size() == 1 ? datasets.get(0).path("digest").asText() : null;
        if (r.underAllocLoad()) {
            // the spec writes them "200,64"; the summary of a run the spec does not tell, under parameters.load
            String[] rates = s.path("loadAlloc").asText("").split(",");
            if (rates.length == 2 && rates[0].strip().matches("\\d+") && rates[1].strip().matches("\\d+")) {
                r.allocMbPerS = Integer.valueOf(rates[0].strip());
                r.allocLiveMb = Integer.valueOf(rates[1].strip());
            } else if (p.at("/load/allocMbPerS").isInt() && p.at("/load/allocLiveMb").isInt()) {
                r.allocMbPerS = p.at("/load/allocMbPerS").asInt();
                r.allocLiveMb = p.at("/load/allocLiveMb").asInt();
            }
        }
    }

    private static Object nullable(ResultSet rs, int column, boolean integer) throws SQLException {
        if (integer) {
            long v = rs.getLong(column);
            return rs.wasNull() ? null : v;
        }
        double v = rs.getDouble(column);
        return rs.wasNull() ? null : v;
    }

    private boolean hasColumn(String table, String column) {
        try (PreparedStatement ps = conn.prepareStatement("SELECT count(*) FROM pragma_table_info(?) WHERE name = ?")) {
            ps.setString(1, table);
            ps.setString(2, column);
            try (ResultSet rs = ps.executeQuery()) {
                return rs.next() && rs.getInt(1) > 0;
            }
        } catch (SQLException e) {
            return false;
        }
    }

    /** Every machine, by id. */
    public Map<String, Machine> machines() {
        Map<String, Machine> out = new LinkedHashMap<>();
        if (!hasTable("machines")) {
            return out;
        }
        try (Statement st = conn.createStatement();
             ResultSet rs = st.executeQuery("SELECT machine_id, hostname, kernel, cpu_model, processors, doctor_json FROM machines ORDER BY machine_id")) {
            while (rs.next()) {
                int p = rs.getInt(5);
                Integer processors = rs.wasNull() ? null : p;
                out.put(rs.getString(1), new Machine(rs.getString(1), rs.getString(2), rs.getString(3), rs.getString(4),
                        processors, rs.getString(6)));
            }
        } catch (SQLException e) {
            throw new IllegalStateException(file + ": " + ResultsDatabase.oneLine(e.getMessage()), e);
        }
        return out;
    }

    /** The decoded histograms of one task/metric for each of {@code runKeys} (missing ones left out). */
    public Map<String, Histogram> histograms(List<String> runKeys, String task, String metric) {
        Map<String, Histogram> out = new HashMap<>();
        if (!hasTable("histograms")) {
            return out;
        }
        try (PreparedStatement ps = conn.prepareStatement("SELECT hdr FROM histograms WHERE run_key = ? AND task = ? AND metric = ?")) {
            for (String key : runKeys) {
                ps.setString(1, key);
                ps.setString(2, task);
                ps.setString(3, metric);
                try (ResultSet rs = ps.executeQuery()) {
                    if (rs.next() && rs.getString(1) != null) {
                        Histogram h = decode(rs.getString(1));
                        if (h != null) {
                            out.put(key, h);
                        }
                    }
                }
            }
        } catch (SQLException e) {
            throw new IllegalStateException(file + ": " + ResultsDatabase.oneLine(e.getMessage()), e);
        }
        return out;
    }

    /** Base64 of HdrHistogram's compressed encoding -> histogram; null when it cannot be decoded. */
    public static Histogram decode(String base64) {
        try {
            byte[] bytes = Base64.getDecoder().decode(base64.trim());
            return Histogram.decodeFromCompressedByteBuffer(ByteBuffer.wrap(bytes), 0);
        } catch (IllegalArgumentException | DataFormatException | java.nio.BufferUnderflowException e) {
            return null;
        }
    }

    /** The series JSON of one run by name, or null. */
    public String series(String runKey, String name) {
        if (!hasTable("series")) {
            return null;
        }
        try (PreparedStatement ps = conn.prepareStatement("SELECT json FROM series WHERE run_key = ? AND name = ?")) {
            ps.setString(1, runKey);
            ps.setString(2, name);
            try (ResultSet rs = ps.executeQuery()) {
                return rs.next() ? rs.getString(1) : null;
            }
        } catch (SQLException e) {
            throw new IllegalStateException(file + ": " + ResultsDatabase.oneLine(e.getMessage()), e);
        }
    }

    private final Map<String, Boolean> tables = new HashMap<>();

    private boolean hasTable(String name) {
        return tables.computeIfAbsent(name, n -> {
            try (PreparedStatement ps = conn.prepareStatement("SELECT count(*) FROM sqlite_master WHERE type='table' AND name=?")) {
                ps.setString(1, n);
                try (ResultSet rs = ps.executeQuery()) {
                    return rs.next() && rs.getInt(1) > 0;
                }
            } catch (SQLException e) {
                return false;
            }
        });
    }

    private static String nz(String s, String dflt) {
        return s == null ? dflt : s;
    }

    @Override
    public void close() {
        try {
            database.close();
        } catch (SQLException e) {
            // read-only: nothing to lose
        }
    }

    /**
     * The engine of a run from its summary's parameters ({@code fallback} when they name none): an
     * rtsj run's design is part of its engine, {@code rtsj} (thesis) or {@code rtsj-atomic}.
     */
    public static String engineOf(com.fasterxml.jackson.databind.JsonNode parameters, String fallback) {
        String engine = parameters.path("engine").asText(fallback);
        return "rtsj".equals(engine) && "atomic".equals(parameters.path("rtsjDesign").asText()) ? "rtsj-atomic" : engine;
    }
}
