package org.jmclbench.tooling.store;

/** The results store's SQL schema (docs/FORMATS.md section 5); {@code PRAGMA user_version} is {@link #VERSION}. */
final class Schema {
    static final int VERSION = 1;

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
          command_json TEXT
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
        "CREATE INDEX IF NOT EXISTS runs_by_config ON runs (runtime, profile, policy, particles, dataset)",
        org.jmclbench.tooling.attribution.AttributionStore.SCHEMA,
    };

    /** Tables keyed by run, in the order a run's rows are copied or deleted. */
    static final String[] RUN_TABLES = {"runs", "metrics", "histograms", "series", "attributions"};

    private Schema() {
    }
}
