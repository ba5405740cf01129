package org.jmclbench.tooling.store;

/**
 * The results store's SQL schema (docs/FORMATS.md section 5); {@code PRAGMA user_version} is {@link #VERSION}.
 * Version 2 added the runs' engine and memory style and the {@code memory_areas} table; version 3 the
 * jmclbench commit that made each run ({@code code_version}, null in the runs stored before it). An
 * older store is migrated when opened for writing ({@link #ADDED_RUN_COLUMNS}, {@link #FILL_ENGINES}).
 */
final class Schema {
    static final int VERSION = 3;
    /** The oldest version this tool reads and migrates. */
    static final int OLDEST = 1;

    static final String[] CREATE = {
        """
        CREATE TABLE IF NOT EXISTS machines (
          machine_id TEXT PRIMARY KEY,
          hostname TEXT, kernel TEXT, cpu_model TEXT, processors INTEGER,
          doctor_json TEXT
        )""",
        """
        CREATE TABLE IF NOT EXISTS matrices (
          matrix_id TEXT PRIMARY KEY, machine_id TEXT, command TEXT, order_seed INTEGER,
          started_at TEXT, spec_json TEXT
        )""",
        """
        CREATE TABLE IF NOT EXISTS runs (
          run_key TEXT PRIMARY KEY,
          matrix_id TEXT, machine_id TEXT,
          runtime TEXT, runtime_version TEXT, profile TEXT,
          policy TEXT, particles INTEGER, dataset TEXT, load TEXT, repetition INTEGER,
          status TEXT NOT NULL CHECK (status IN ('ok', 'failed', 'timeout', 'unsupported')),
          exit_code INTEGER, failure TEXT, stderr_tail TEXT,
          started_at TEXT, ended_at TEXT, wall_s REAL,
          run_dir TEXT,
          summary_json TEXT,
          seed INTEGER,
          command_json TEXT,
          engine TEXT,
          memory TEXT,
          code_version TEXT
        )""",
        """
        CREATE TABLE IF NOT EXISTS metrics (
          run_key TEXT, task TEXT, metric TEXT, stat TEXT, value REAL,
          PRIMARY KEY (run_key, task, metric, stat)
        )""",
        """
        CREATE TABLE IF NOT EXISTS histograms (
          run_key TEXT, task TEXT, metric TEXT, hdr TEXT,
          PRIMARY KEY (run_key, task, metric)
        )""",
        """
        CREATE TABLE IF NOT EXISTS series (
          run_key TEXT, name TEXT, json TEXT,
          PRIMARY KEY (run_key, name)
        )""",
        """
        CREATE TABLE IF NOT EXISTS memory_areas (
          run_key TEXT, name TEXT, size INTEGER, peak_bytes INTEGER, bytes_per_release REAL,
          PRIMARY KEY (run_key, name)
        )""",
        "CREATE INDEX IF NOT EXISTS runs_by_config ON runs (runtime, profile, policy, particles, dataset)",
        org.jmclbench.tooling.attribution.AttributionStore.SCHEMA,
    };

    /**
     * Tables and columns every version has (the first word is the table): a file that lacks them is not a
     * store, though it has a runs table, and a merge or report would fail on it part way.
     */
    static final String[][] REQUIRED = {
        {"machines", "machine_id", "hostname", "kernel", "cpu_model", "processors", "doctor_json"},
        {"matrices", "matrix_id", "machine_id", "command", "order_seed", "started_at", "spec_json"},
        {"runs", "run_key", "status"},
    };

    /** Tables keyed by run, in the order a run's rows are copied or deleted. */
    static final String[] RUN_TABLES = {"runs", "metrics", "histograms", "series", "attributions", "memory_areas"};

    /**
     * Columns of {@code runs} added after its first version, in order: a store that lacks them gets
     * them appended (so that its column order is a new store's).
     */
    static final String[][] ADDED_RUN_COLUMNS = {
        {"seed", "INTEGER"}, {"command_json", "TEXT"}, {"engine", "TEXT"}, {"memory", "TEXT"}, {"code_version", "TEXT"},
    };

    /**
     * Fills the engine and memory style of runs that have none (made before version 2): the
     * native baseline's runs are engine {@code native}, every other run was the Java SE engine;
     * the memory style is the summary's, else the one passed on the command line
     * ({@code --workload-arg "--memory allocating"}), else preallocated.
     */
    static final String[] FILL_ENGINES = {
        "UPDATE runs SET engine = CASE WHEN runtime = 'native' THEN 'native' ELSE 'javase' END WHERE engine IS NULL",
        """
        UPDATE runs SET memory = COALESCE(
          CASE WHEN json_valid(summary_json) THEN json_extract(summary_json, '$.parameters.memory') END,
          CASE WHEN command_json LIKE '%"--memory","allocating"%' THEN 'allocating' END,
          'preallocated') WHERE memory IS NULL""",
    };

    private Schema() {
    }
}
