package org.jmclbench.tooling.report;

import java.nio.ByteBuffer;
import java.nio.file.Files;
import java.nio.file.Path;
import java.sql.Connection;
import java.sql.DriverManager;
import java.sql.PreparedStatement;
import java.sql.SQLException;
import java.sql.Statement;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Base64;
import java.util.List;
import java.util.Locale;
import java.util.SplittableRandom;

import org.HdrHistogram.Histogram;
import org.jmclbench.tooling.store.StoredRun;

import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;

/**
 * Makes results databases with the schema of docs/FORMATS.md section 5 and realistic rows
 * (summary.json per section 4, flattened metrics, HdrHistogram histograms, series), for the
 * report's tests and for its benchmark ({@code main}: a database of any number of runs).
 */
public final class FixtureDb {

    /** The store's schema, as written in docs/FORMATS.md section 5 (version 2: engines and memory areas). */
    public static final String SCHEMA = """
            CREATE TABLE machines (machine_id TEXT PRIMARY KEY, hostname TEXT, kernel TEXT, cpu_model TEXT, processors INTEGER, doctor_json TEXT);
            CREATE TABLE matrices (matrix_id TEXT PRIMARY KEY, machine_id TEXT, command TEXT, order_seed INTEGER, started_at TEXT, spec_json TEXT);
            CREATE TABLE runs (run_key TEXT PRIMARY KEY, matrix_id TEXT, machine_id TEXT, runtime TEXT, runtime_version TEXT, profile TEXT,
              policy TEXT, particles INTEGER, dataset TEXT, load TEXT, repetition INTEGER, status TEXT, exit_code INTEGER, failure TEXT,
              stderr_tail TEXT, started_at TEXT, ended_at TEXT, wall_s REAL, run_dir TEXT, summary_json TEXT, seed INTEGER,
              command_json TEXT, engine TEXT, memory TEXT);
            CREATE TABLE memory_areas (run_key TEXT, name TEXT, size INTEGER, peak_bytes INTEGER, bytes_per_release REAL,
              PRIMARY KEY (run_key, name));
            CREATE TABLE metrics (run_key TEXT, task TEXT, metric TEXT, stat TEXT, value REAL, PRIMARY KEY (run_key, task, metric, stat));
            CREATE TABLE histograms (run_key TEXT, task TEXT, metric TEXT, hdr TEXT, PRIMARY KEY (run_key, task, metric));
            CREATE TABLE series (run_key TEXT, name TEXT, json TEXT, PRIMARY KEY (run_key, name));
            """;

    /** The schema of a store made before engines (version 1): no engine, memory style or areas. */
    static final String LEGACY_SCHEMA = SCHEMA
            .replace(", seed INTEGER,\n              command_json TEXT, engine TEXT, memory TEXT);", ");")
            .replaceAll("(?s)CREATE TABLE memory_areas.*?;\n", "");

    /**
     * A runtime configuration of the fixture; {@code speed} multiplies the job cost (native = 1).
     *
     * @param engine javase, scj or native (the native runtime's)
     * @param memory preallocated, allocating or scoped
     */
    public record Config(String runtime, String profile, String version, double speed, String status, String engine,
                         String memory) {
        public Config(String runtime, String profile, String version, double speed, String status) {
            this(runtime, profile, version, speed, status, "native".equals(runtime) ? "native" : "javase", "preallocated");
        }

        public String id() {
            return profile.isEmpty() ? runtime : runtime + "/" + profile;
        }

        /** {@link #id()} with the engine and memory style, so that run keys differ. */
        String key() {
            return id() + "-" + engine + "-" + memory;
        }
    }

    /** Write a store of schema version 1 (before engines), to check that the report still reads one. */
    public boolean legacySchema;

    private static final ObjectMapper JSON = new ObjectMapper();

    public List<Config> configs = new ArrayList<>(List.of(
            new Config("native", "", "gcc 12.2.0", 1.0, "ok"),
            new Config("temurin-17", "g1", "17.0.15+6", 1.3, "ok"),
            new Config("temurin-25", "zgc", "25+36", 1.15, "ok")));
    public List<String> datasets = List.of("match-short");
    public List<String> policies = List.of("skip", "terminate");
    public List<Integer> particles = List.of(100, 400, 1600);
    /** The load scenarios every setting runs under ({@code none}: an idle machine). */
    public List<String> loads = List.of("none");
    /** Store each task's response-time histogram (a store before them has none). */
    public boolean responseHistograms = true;
    /** Write deadlineMisses, missRatio and responseTimeReleasedNs in the summaries (a run before them has none). */
    public boolean deadlineAccounting = true;
    public int repetitions = 3;
    /** Whether a run (configuration, repetition) has no attribution rows: its runtime left no evidence the harness could read. */
    public java.util.function.BiPredicate<Config, Integer> unattributed = (cfg, rep) -> false;
    /**
     * Per configuration id, a factor on its release jitter (1 where absent): a runtime slower to release, not to
     * compute. A key with a load label ({@code "native [load cpu]"}) scales only the runs beside that load.
     */
    public java.util.Map<String, Double> jitterScale = java.util.Map.of();
    /** Per configuration id, keyed as {@link #jitterScale}, a factor on its jobs' cost: a runtime faster or slower to compute. */
    public java.util.Map<String, Double> costScale = java.util.Map.of();
    /** Length of the replayed timeline in seconds (odometry every 50 ms, laser about 3.6 per second). */
    public double durationS = 12.0;
    public long seed = 1;

    /** Writes the database (replacing any file at {@code db}); returns the number of runs. */
    public int write(Path db) throws Exception {
        Files.deleteIfExists(db);
        if (db.getParent() != null) {
            Files.createDirectories(db.getParent());
        }
        SplittableRandom rng = new SplittableRandom(seed);
        int runs = 0;
        try (Connection c = DriverManager.getConnection("jdbc:sqlite:" + db.toAbsolutePath())) {
            c.setAutoCommit(false);
            try (Statement st = c.createStatement()) {
                for (String sql : (legacySchema ? LEGACY_SCHEMA : SCHEMA).split(";")) {
                    if (!sql.isBlank()) {
                        st.execute(sql);
                    }
                }
                st.execute("PRAGMA user_version = " + (legacySchema ? 1 : 2));
            }
            insertMachine(c);
            try (PreparedStatement run = c.prepareStatement("INSERT INTO runs (run_key, matrix_id, machine_id, runtime,"
                    + " runtime_version, profile, policy, particles, dataset, load, repetition, status, exit_code, failure,"
                    + " stderr_tail, started_at, ended_at, wall_s, run_dir, summary_json"
                    + (legacySchema ? ")" : ", engine, memory)") + " VALUES (?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?"
                    + (legacySchema ? ")" : ",?,?)"));
                 PreparedStatement area = c.prepareStatement(legacySchema ? "SELECT 1"
                         : "INSERT INTO memory_areas VALUES (?,?,?,?,?)");
                 PreparedStatement metric = c.prepareStatement("INSERT INTO metrics VALUES (?,?,?,?,?)");
                 PreparedStatement hist = c.prepareStatement("INSERT INTO histograms VALUES (?,?,?,?)");
                 PreparedStatement series = c.prepareStatement("INSERT INTO series VALUES (?,?,?)")) {
                for (String dataset : datasets) {
                    for (String policy : policies) {
                        for (int p : particles) {
                            for (Config cfg : configs) {
                                for (String load : loads) {
                                    for (int rep = 1; rep <= repetitions; rep++) {
                                        insertRun(run, metric, hist, series, rng, dataset, policy, p, cfg, load, rep);
                                        if (!legacySchema && "ok".equals(cfg.status())) {
                                            insertAreas(area, runKey(dataset, policy, p, cfg, load, rep), p, cfg);
                                        }
                                        runs++;
                                    }
                                }
                            }
                        }
                    }
                }
                run.executeBatch();
                if (!legacySchema) {
                    area.executeBatch();
                }
                metric.executeBatch();
                hist.executeBatch();
                series.executeBatch();
            }
            c.commit();
        }
        return runs;
    }

    private static void insertMachine(Connection c) throws SQLException {
        ArrayNode doctor = JSON.createArrayNode();
        doctor.addObject().put("check", "virtualization").put("status", "warn").put("value", "kvm")
                .put("advice", "a virtual machine adds jitter; prefer bare metal");
        doctor.addObject().put("check", "cpu governor").put("status", "ok").put("value", "performance").put("advice", "");
        doctor.addObject().put("check", "clocksource").put("status", "ok").put("value", "kvm-clock").put("advice", "");
        try (PreparedStatement ps = c.prepareStatement("INSERT INTO machines VALUES (?,?,?,?,?,?)")) {
            ps.setString(1, "m-1");
            ps.setString(2, "bench-host");
            ps.setString(3, "6.1.0-27-amd64");
            ps.setString(4, "Intel(R) Xeon(R) CPU @ 2.20GHz");
            ps.setInt(5, 2);
            ps.setString(6, doctor.toString());
            ps.executeUpdate();
            try (PreparedStatement m = c.prepareStatement("INSERT INTO matrices VALUES ('x-1','m-1','jmclbench quick',7,'2026-11-22T02:00:00Z','{}')")) {
                m.executeUpdate();
            }
        }
    }

    private static String runKey(String dataset, String policy, int particles, Config cfg, String load, int rep) {
        return String.format(Locale.ROOT, "%s-%s-%s-%d-%s-%d", dataset, policy, cfg.key().replaceAll("[^A-Za-z0-9]", "_"),
                particles, Integer.toHexString(cfg.key().hashCode()), rep) + ("none".equals(load) ? "" : "-" + load);
    }

    /**
     * The memory areas the engines report: the Java SE engine's heap (allocating: more), the SCJ
     * engine's immortal, mission and the two handlers' private memories (scoped: what a release
     * allocates there), none for native. Made-up sizes that grow with the particles.
     */
    static void insertAreas(PreparedStatement ps, String key, int particles, Config cfg) throws SQLException {
        List<Object[]> areas = new ArrayList<>();
        boolean scoped = "scoped".equals(cfg.memory());
        switch (cfg.engine()) {
            case "javase" -> areas.add(new Object[] {"heap", 512L << 20, 2_000_000L + particles * ("allocating".equals(cfg.memory()) ? 9000L : 1000L),
                    "allocating".equals(cfg.memory()) ? particles * 50.0 : 0.0});
            case "scj" -> {
                areas.add(new Object[] {"immortal", 1L << 20, 120_000L, null});
                areas.add(new Object[] {"mission", 4L << 20, 5_000L + particles * 100L, null});
                areas.add(new Object[] {"predict", 256L << 10, scoped ? particles * 40L : 0L, scoped ? particles * 40.0 : 0.0});
                areas.add(new Object[] {"update", 256L << 10, scoped ? particles * 80L : 0L, scoped ? particles * 80.0 : 0.0});
            }
            default -> { }
        }
        for (Object[] a : areas) {
            ps.setString(1, key);
            ps.setString(2, (String) a[0]);
            ps.setLong(3, (Long) a[1]);
            ps.setLong(4, (Long) a[2]);
            ps.setObject(5, a[3]);
            ps.addBatch();
        }
    }

    private void insertRun(PreparedStatement run, PreparedStatement metric, PreparedStatement hist, PreparedStatement series,
                           SplittableRandom rng, String dataset, String policy, int particles, Config cfg, String load, int rep)
            throws Exception {
        String key = runKey(dataset, policy, particles, cfg, load, rep);
        if (!legacySchema) {
            run.setString(21, cfg.engine());
            run.setString(22, cfg.memory());
        }
        run.setString(1, key);
        run.setString(2, "x-1");
        run.setString(3, "m-1");
        run.setString(4, cfg.runtime());
        run.setString(5, cfg.version());
        run.setString(6, cfg.profile());
        run.setString(7, policy);
        run.setInt(8, particles);
        run.setString(9, dataset);
        run.setString(10, load);
        run.setInt(11, rep);
        run.setString(12, cfg.status());
        run.setString(16, "2026-11-22T02:10:00Z");
        run.setString(17, "2026-11-22T02:10:13Z");
        run.setDouble(18, durationS + 1);
        run.setString(19, "runs/" + key);
        if (!"ok".equals(cfg.status())) {
            run.setInt(13, "unsupported".equals(cfg.status()) ? 1 : 134);
            run.setString(14, "unsupported".equals(cfg.status()) ? "not supported: Unrecognized VM option 'UseShenandoahGC'"
                    : "crashed <b>bold</b> & exit 134");
            run.setString(15, "Error: <img src=x onerror=alert(2)>\nUnrecognized VM option");
            run.setNull(20, java.sql.Types.VARCHAR);
            run.addBatch();
            return;
        }
        run.setInt(13, 0);
        run.setNull(14, java.sql.Types.VARCHAR);
        run.setString(15, "");

        // Jobs: cost grows with particles; under skip/terminate jobs longer than the period are missed.
        double periodMs = 50;
        int predictJobs = (int) (durationS / 0.05);
        int updateJobs = (int) (durationS * 3.6);
        String loaded = cfg.id() + ("none".equals(load) ? "" : StoredRun.loadLabel(load));
        double costMs = 0.004 * particles * cfg.speed() * (1 + 0.05 * rng.nextDouble())
                * costScale.getOrDefault(loaded, costScale.getOrDefault(cfg.id(), 1.0));
        double jitterFactor = jitterScale.getOrDefault(loaded, jitterScale.getOrDefault(cfg.id(), 1.0));
        Job[] predict = jobs(rng, predictJobs, costMs * 0.3, cfg.speed(), periodMs, jitterFactor);
        Job[] update = jobs(rng, updateJobs, costMs, cfg.speed(), 1000 / 3.6, jitterFactor);
        Job[] all = concat(predict, update);
        int missPredict = (int) Arrays.stream(predict).filter(j -> j.latencyNs > 45e6 * (0.9 + 0.2 * rng.nextDouble())).count()
                + (int) Math.round(particles / 400.0 * cfg.speed() * rng.nextDouble() * 2);
        int missUpdate = (int) Math.round(particles / 800.0 * (cfg.speed() - 0.9) * 4 * rng.nextDouble());
        double deviation = 0.02 + 2.0 / Math.sqrt(particles) * 0.05 + 0.01 * rng.nextDouble() + 0.001 * (missPredict + missUpdate);

        ObjectNode s = JSON.createObjectNode();
        s.put("schema", "jmclbench-run/1").put("status", "complete");
        ObjectNode params = s.putObject("parameters");
        params.put("runtimeName", cfg.runtime()).put("particles", particles).put("number", rep).put("policy", policy)
                .put("ideal", false).put("engine", cfg.engine()).put("memory", cfg.memory()).put("estimate", "mean").put("resample", "systematic")
                .put("init", "known").put("seed", 1).put("covariance", false).put("timeScale", 1.0).put("warmupS", 0.0).put("spinUs", 0);
        params.putObject("dataset").put("path", "data/" + dataset).put("scenario", "match");
        if (legacySchema) {
            params.remove("engine"); // a workload before engines did not write it
        }
        ObjectNode env = s.putObject("environment");
        ObjectNode rt = env.putObject("runtime");
        boolean nat = "native".equals(cfg.runtime());
        rt.put("language", nat ? "c" : "java").put("name", cfg.runtime()).put("vendor", nat ? "gcc" : "Eclipse Adoptium")
                .put("version", cfg.version()).put("vmName", nat ? "native" : "OpenJDK 64-Bit Server VM");
        ArrayNode args = rt.putArray("inputArguments");
        if (nat) {
            args.add("run").add("-n").add("1").add("--seed").add("1"); // the native baseline reports its argv
        } else {
            args.add("-XX:+Use" + (cfg.profile().isEmpty() ? "G1" : cfg.profile().toUpperCase(Locale.ROOT).replace("ZGC", "Z")) + "GC");
            args.add("-Xms256m");
            // what the runner adds to every JVM run (JfrFlags): a recording of this run's own, and the home
            args.add("-XX:StartFlightRecording=filename=/results/runs/" + key + "/recording.jfr,settings=/results/runs/" + key
                    + "/jmclbench.jfc,dumponexit=true").add("-Djmclbench.home=/opt/jmclbench");
        }
        env.putObject("os").put("name", "Linux").put("arch", "amd64").put("kernel", "6.1.0-27-amd64");
        env.putObject("cpu").put("model", "Intel(R) Xeon(R) CPU @ 2.20GHz").put("processors", 2);
        env.putObject("scheduling").put("policy", "SCHED_OTHER").put("priority", 0);
        env.put("clocksource", "kvm-clock").put("hostname", "bench-host").put("startedAt", "2026-11-22T02:10:00Z");
        ObjectNode engineNode = s.putObject("engine");
        if (!legacySchema) {
            engineNode.put("kind", cfg.engine());
        }
        engineNode.put("dispatcherPriority", 10).put("handlerPriority", 9).put("prioritiesApplied", nat)
                .put("cpuTime", "used (allocation-free)").putNull("gcLog").put("warmupEvents", 0).put("allocatedBytes", 0);
        s.put("durationS", durationS);
        int missCount = missPredict + missUpdate;
        s.put("missCount", missCount);
        ObjectNode tasks = s.putObject("tasks");
        task(tasks.putObject("predict"), predict, missPredict, deadlineAccounting);
        task(tasks.putObject("update"), update, missUpdate, deadlineAccounting);
        task(tasks.putObject("all"), all, missCount, deadlineAccounting);
        stats(s.putObject("dispatcherLatenessNs"), Arrays.stream(all).mapToDouble(j -> j.jitterNs * 0.8).toArray());
        ObjectNode dev = s.putObject("deviation");
        dev.putObject("xy").put("mean", deviation).put("max", deviation * 3);
        dev.putObject("x").put("mean", deviation * 0.6).put("max", deviation * 2);
        dev.putObject("y").put("mean", deviation * 0.6).put("max", deviation * 2);
        dev.putObject("angle").put("mean", 0.02).put("max", 0.1);
        run.setString(20, s.toString());
        run.addBatch();

        for (String t : List.of("predict", "update", "all")) {
            ObjectNode tn = (ObjectNode) tasks.get(t);
            for (String m : List.of("releaseJitterNs", "taskLatencyNs", "responseTimeNs", "cpuNs")) {
                tn.get(m).fields().forEachRemaining(e -> addMetric(metric, key, t, m, e.getKey(), e.getValue().isNull() ? null : e.getValue().asDouble()));
            }
            for (String m : List.of("missCount", "late", "skipped", "terminated", "released")) {
                addMetric(metric, key, t, m, "value", tn.get(m).asDouble());
            }
        }
        addMetric(metric, key, "run", "missCount", "value", (double) missCount);
        s.get("dispatcherLatenessNs").fields().forEachRemaining(e -> addMetric(metric, key, "dispatcher", "latenessNs", e.getKey(), e.getValue().asDouble()));
        addMetric(metric, key, "run", "deviationXY", "mean", deviation);
        addMetric(metric, key, "run", "deviationX", "mean", deviation * 0.6);
        addMetric(metric, key, "run", "deviationY", "mean", deviation * 0.6);
        addMetric(metric, key, "run", "deviationAngle", "mean", 0.02);

        for (String t : List.of("predict", "update", "all")) {
            Job[] jobs = t.equals("predict") ? predict : t.equals("update") ? update : all;
            addHistogram(hist, key, t, "taskLatencyNs", jobs, j -> j.latencyNs);
            addHistogram(hist, key, t, "releaseJitterNs", jobs, j -> j.jitterNs);
            if (responseHistograms) {
                addHistogram(hist, key, t, "responseTimeNs", jobs, j -> j.latencyNs + j.jitterNs); // completed jobs only
            }
            if (policy.equals("terminate")) {
                addAbortHistogram(hist, key, t, jobs);
            }
        }

        // Columns as the runner's ingest writes them (the outcome column is text there; a number here).
        List<String> latencyColumns = List.of("index", "releaseS", "taskLatencyNs", "responseTimeNs", "outcome");
        addSeries(series, key, "taskLatency.predict", latencyColumns, predict.length,
                i -> new double[] {i, i * 0.05, predict[i].latencyNs, predict[i].latencyNs + predict[i].jitterNs, 0});
        addSeries(series, key, "taskLatency.update", latencyColumns, update.length,
                i -> new double[] {i, i / 3.6, update[i].latencyNs, update[i].latencyNs + update[i].jitterNs, 0});
        if (!unattributed.test(cfg, rep)) {
            addAttribution(metric, series, key, cfg, missCount, predict);
        }
        double phase = rng.nextDouble();
        addSeries(series, key, "deviation", List.of("time", "dx", "dy", "dxy", "dtheta"), predictJobs, i -> {
            double d = deviation * (1 + 0.8 * Math.sin(i * 0.02 + phase * 6));
            return new double[] {i * 0.05, d * 0.7, d * 0.7, d, 0.01};
        });
        addSeries(series, key, "trajectory", List.of("time", "x", "y", "theta", "realX", "realY", "realTheta"), predictJobs, i -> {
            double a = 2 * Math.PI * i / predictJobs;
            double rx = 1.5 + 0.9 * Math.sin(a);
            double ry = 1.0 + 0.6 * Math.sin(2 * a);
            double e = deviation * Math.sin(a * 7 + phase);
            return new double[] {i * 0.05, rx + e, ry - e, a, rx, ry, a};
        });
    }

    /** The attribution's rows as the runner writes them: causes (the primary split of the misses), the warm-up split, the pauses. */
    private static void addAttribution(PreparedStatement metric, PreparedStatement series, String key, Config cfg, int missCount,
                                       Job[] predict) throws SQLException {
        boolean java = !"native".equals(cfg.runtime());
        List<String> kinds = java ? CAUSES_JAVA : CAUSES_NATIVE;
        int left = missCount;
        for (int k = 0; k < kinds.size(); k++) {
            int share = k == kinds.size() - 1 ? left : left / 2; // halves: compute, then the VM's causes, ...
            left -= share;
            addMetric(metric, key, "run", "cause." + kinds.get(k), "primary", (double) share);
            addMetric(metric, key, "run", "cause." + kinds.get(k), "count", (double) share + 1);
        }
        addMetric(metric, key, "run", "cause.jobs", "count", (double) missCount);
        int warmJobs = Math.min(40, predict.length);
        double warmP99 = 0;
        double steadyP99 = 0;
        for (int i = 0; i < predict.length; i++) {
            if (i < warmJobs) {
                warmP99 = Math.max(warmP99, predict[i].latencyNs);
            } else {
                steadyP99 = Math.max(steadyP99, predict[i].latencyNs);
            }
        }
        addMetric(metric, key, "all", "taskLatencyNs.warm", "p99", warmP99 * (java ? 3 : 1));
        addMetric(metric, key, "all", "taskLatencyNs.steady", "p99", steadyP99);
        addMetric(metric, key, "all", "missedOrLate.warm", "value", (double) (java ? missCount / 2 : 0));
        addMetric(metric, key, "all", "missedOrLate.steady", "value", (double) (missCount - (java ? missCount / 2 : 0)));
        addMetric(metric, key, "all", "released.warm", "value", (double) warmJobs);
        addMetric(metric, key, "all", "released.steady", "value", (double) (predict.length - warmJobs));
        if (java) {
            ObjectNode o = JSON.createObjectNode();
            o.putArray("columns").add("start").add("end").add("kind").add("detail");
            ArrayNode rows = o.putArray("rows");
            for (double t = 0.4; t < predict.length * 0.05; t += 7.5) {
                rows.addArray().add(t).add(t + 0.6).add("gc").add("G1 Evacuation Pause");
                rows.addArray().add(t + 3).add(t + 3.3).add("safepoint").add("Deoptimize");
            }
            series.setString(1, key);
            series.setString(2, "pauses");
            series.setString(3, o.toString());
            series.addBatch();
        }
    }

    /** The cause kinds the fixture attributes misses to (FORMATS.md 5), in the order their shares halve. */
    static final List<String> CAUSES_JAVA = List.of("compute", "gc", "jit", "safepoint", "os");
    static final List<String> CAUSES_NATIVE = List.of("compute", "os");

    private record Job(double latencyNs, double jitterNs) {
    }

    private static Job[] jobs(SplittableRandom rng, int n, double costMs, double speed, double periodMs, double jitterFactor) {
        Job[] out = new Job[n];
        for (int i = 0; i < n; i++) {
            double spike = rng.nextDouble() < 0.01 * speed ? rng.nextDouble() * 8 * speed : 0;
            double latency = Math.max(0.01, costMs * (1 + 0.1 * gauss(rng)) + spike) * 1e6;
            double jitter = (0.05 + 0.04 * Math.abs(gauss(rng)) * speed + (rng.nextDouble() < 0.02 ? rng.nextDouble() * speed : 0)) * 1e6;
            out[i] = new Job(Math.min(latency, periodMs * 2e6), jitter * jitterFactor);
        }
        return out;
    }

    private static double gauss(SplittableRandom rng) {
        double s = 0;
        for (int i = 0; i < 12; i++) {
            s += rng.nextDouble();
        }
        return s - 6;
    }

    private static Job[] concat(Job[] a, Job[] b) {
        Job[] out = Arrays.copyOf(a, a.length + b.length);
        System.arraycopy(b, 0, out, a.length, b.length);
        return out;
    }

    private static void task(ObjectNode t, Job[] jobs, int missed, boolean deadlineAccounting) {
        t.put("released", jobs.length + missed).put("completed", jobs.length).put("done", jobs.length).put("late", 0)
                .put("skipped", missed).put("terminated", 0).put("missCount", missed).put("deadlineMisses", missed)
                .put("missRatio", (double) missed / (jobs.length + missed));
        double[] lat = Arrays.stream(jobs).mapToDouble(Job::latencyNs).toArray();
        double[] jit = Arrays.stream(jobs).mapToDouble(Job::jitterNs).toArray();
        stats(t.putObject("releaseJitterNs"), jit);
        stats(t.putObject("taskLatencyNs"), lat);
        double[] resp = new double[lat.length];
        for (int i = 0; i < resp.length; i++) {
            resp[i] = lat[i] + jit[i];
        }
        stats(t.putObject("responseTimeNs"), resp);
        stats(t.putObject("cpuNs"), Arrays.stream(lat).map(v -> v * 0.97).toArray());
        if (!deadlineAccounting) {
            return;
        }
        // the deadline accounting of FORMATS.md 4: the skipped jobs never complete (+inf)
        int released = jobs.length + missed;
        t.put("deadlineMisses", missed).put("missRatio", (double) missed / released);
        ObjectNode all = t.putObject("responseTimeReleasedNs").put("count", released).put("completed", jobs.length);
        double[] sorted = resp.clone();
        Arrays.sort(sorted);
        for (String[] q : new String[][] {{"min", "0"}, {"p50", "0.5"}, {"p90", "0.9"}, {"p99", "0.99"}, {"p999", "0.999"}, {"max", "1"}}) {
            int i = Math.max(0, (int) Math.ceil(Double.parseDouble(q[1]) * released) - 1);
            if (i < sorted.length) {
                all.put(q[0], (long) sorted[i]);
            } else {
                all.put(q[0], "inf");
            }
        }
    }

    /** STATS of docs/FORMATS.md 4: nearest-rank percentiles. */
    private static void stats(ObjectNode o, double[] xs) {
        double[] s = xs.clone();
        Arrays.sort(s);
        int n = s.length;
        o.put("count", n).put("mean", Stats.mean(s)).put("stdev", n > 1 ? Stats.stdev(s) : 0.0).put("min", (long) s[0]);
        for (String[] q : new String[][] {{"p50", "0.5"}, {"p90", "0.9"}, {"p99", "0.99"}, {"p999", "0.999"}}) {
            o.put(q[0], (long) s[Math.max(0, (int) Math.ceil(Double.parseDouble(q[1]) * n) - 1)]);
        }
        o.put("max", (long) s[n - 1]);
    }

    private static void addMetric(PreparedStatement ps, String key, String task, String metric, String stat, Double value) {
        try {
            ps.setString(1, key);
            ps.setString(2, task);
            ps.setString(3, metric);
            ps.setString(4, stat);
            if (value == null) {
                ps.setNull(5, java.sql.Types.REAL);
            } else {
                ps.setDouble(5, value);
            }
            ps.addBatch();
        } catch (SQLException e) {
            throw new IllegalStateException(e);
        }
    }

    /** Base64 of HdrHistogram's compressed encoding, values in nanoseconds (3 significant digits). */
    static String encode(Histogram h) {
        ByteBuffer buf = ByteBuffer.allocate(h.getNeededByteBufferCapacity());
        int len = h.encodeIntoCompressedByteBuffer(buf);
        return Base64.getEncoder().encodeToString(Arrays.copyOf(buf.array(), len));
    }

    private static void addHistogram(PreparedStatement ps, String key, String task, String metric, Job[] jobs,
                                     java.util.function.ToDoubleFunction<Job> value) throws SQLException {
        Histogram h = new Histogram(3);
        for (Job j : jobs) {
            h.recordValue((long) value.applyAsDouble(j));
        }
        ps.setString(1, key);
        ps.setString(2, task);
        ps.setString(3, metric);
        ps.setString(4, encode(h));
        ps.addBatch();
    }

    /** Under terminate: every fourth job was asked to abort and ended a quarter of its latency later. */
    private static void addAbortHistogram(PreparedStatement ps, String key, String task, Job[] jobs) throws SQLException {
        Histogram h = new Histogram(3);
        for (int i = 0; i < jobs.length; i += 4) {
            h.recordValue((long) (jobs[i].latencyNs / 4));
        }
        ps.setString(1, key);
        ps.setString(2, task);
        ps.setString(3, "abortLatencyNs");
        ps.setString(4, encode(h));
        ps.addBatch();
    }

    private static void addSeries(PreparedStatement ps, String key, String name, List<String> columns, int n,
                                  java.util.function.IntFunction<double[]> row) throws SQLException {
        ObjectNode o = JSON.createObjectNode();
        ArrayNode cols = o.putArray("columns");
        columns.forEach(cols::add);
        ArrayNode rows = o.putArray("rows");
        for (int i = 0; i < n; i++) {
            ArrayNode r = rows.addArray();
            for (double v : row.apply(i)) {
                r.add(v);
            }
        }
        ps.setString(1, key);
        ps.setString(2, name);
        ps.setString(3, o.toString());
        ps.addBatch();
    }

    /**
     * Writes a benchmark database: {@code FixtureDb OUT.db RUNS}; the runs are spread over 5
     * runtimes, 2 policies, 4 particle counts and as many repetitions as needed, 90 s each.
     */
    public static void main(String[] args) throws Exception {
        if (args.length != 2) {
            System.err.println("usage: FixtureDb OUT.db RUNS");
            System.exit(2);
        }
        FixtureDb f = new FixtureDb();
        f.configs = new ArrayList<>(List.of(
                new Config("native", "", "gcc 12.2.0", 1.0, "ok"),
                new Config("temurin-17", "g1", "17.0.15+6", 1.3, "ok"),
                new Config("temurin-21", "parallel", "21.0.5+11", 1.2, "ok"),
                new Config("temurin-25", "zgc", "25+36", 1.15, "ok"),
                new Config("temurin-25", "shenandoah", "25+36", 1.2, "ok")));
        f.particles = List.of(100, 400, 1600, 3200);
        f.durationS = 90;
        int perRep = f.configs.size() * f.policies.size() * f.particles.size() * f.datasets.size();
        f.repetitions = Math.max(1, (int) Math.ceil(Integer.parseInt(args[1]) / (double) perRep));
        long t0 = System.nanoTime();
        int runs = f.write(Path.of(args[0]));
        System.err.printf(Locale.ROOT, "FixtureDb: %d runs written to %s in %.1f s%n", runs, args[0], (System.nanoTime() - t0) / 1e9);
    }
}
