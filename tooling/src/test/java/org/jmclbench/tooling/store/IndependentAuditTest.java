package org.jmclbench.tooling.store;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.File;
import java.io.IOException;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.sql.Connection;
import java.sql.DriverManager;
import java.sql.ResultSet;
import java.sql.Statement;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.jar.Attributes;
import java.util.jar.JarOutputStream;
import java.util.jar.Manifest;

import org.jmclbench.tooling.Fixtures;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Real runs of the workload through a matrix, then scripts/audit_run.py and scripts/audit_store.py,
 * which share no code with the project: every number of each run's summary.json and data.txt, of the
 * store's metrics, histograms and series, of the report's cells and histogram charts and of compare's
 * table must equal their recomputation from the run folders' job lines and position files.
 */
class IndependentAuditTest {

    private static final Path PROJECT = Path.of(System.getProperty("user.dir")).getParent();

    @TempDir
    Path dir;

    @Test
    void theRunsTheStoreTheReportAndCompareAgreeWithAnIndependentRecomputation() throws Exception {
        Assumptions.assumeTrue(python3Available(), "python3 is not installed (scripts/install-deps.sh installs it)");
        Fixtures.home(dir);
        workloadJarOfThisClassPath(dir.resolve("workload/target/jmclbench-workload.jar"));
        Path db = dir.resolve("results/results.db");
        String java = ProcessHandle.current().info().command().orElse("java");
        // 10 repetitions a side, so that compare applies the separation rule (docs/REPORT.md: 10 runs a side) and
        // the audit recomputes its p-values and verdicts; 1 s of match-quick at 1000 particles keeps the 20 runs short
        Fixtures.CliResult m = Fixtures.cli("matrix", "--java", java, "--engines", "javase,rtsj-atomic",
                "--policies", "skip", "--particles", "1000", "--repeat", "10", "--datasets", PROJECT.resolve("data/match-quick").toString(),
                "--time-scale", "0.1", "--db", db.toString());
        assertEquals(0, m.exitCode(), m.out() + m.err());
        List<String> runDirs = new ArrayList<>();
        String runtime = null;
        try (Connection c = DriverManager.getConnection("jdbc:sqlite:" + db); Statement s = c.createStatement();
             ResultSet rs = s.executeQuery("SELECT runtime, run_dir, status FROM runs")) {
            while (rs.next()) {
                assertEquals("ok", rs.getString(3), m.out() + m.err());
                runtime = rs.getString(1);
                runDirs.add(db.getParent().resolve(rs.getString(2)).toString());
            }
        }
        assertEquals(20, runDirs.size());

        List<String> run = new ArrayList<>(List.of(PROJECT.resolve("scripts/audit_run.py").toString()));
        run.addAll(runDirs);
        assertAgrees(python(run));
        assertExplainAgrees(db, runDirs);

        Fixtures.CliResult report = Fixtures.cli("report", "--db", db.toString(), "--no-export");
        assertEquals(0, report.exitCode(), report.out() + report.err());
        Fixtures.CliResult compare = Fixtures.cli("compare", "--db", db.toString(), "--a", runtime, "--b", runtime + "/rtsj-atomic");
        assertEquals(0, compare.exitCode(), compare.out() + compare.err());
        Path compareOut = dir.resolve("compare.txt");
        Files.writeString(compareOut, compare.out());
        // the evaluation document of this store: its miss ratios' Wilson intervals are audited too
        Path figures = dir.resolve("evaluation/figures");
        Fixtures.CliResult evaluate = Fixtures.cli("evaluate", "--no-run", "--db", db.toString(), "--out", figures.toString(),
                "--matrix", PROJECT.resolve("evaluation/matrix.txt").toString(), "--verification", dir.resolve("none.json").toString());
        assertEquals(0, evaluate.exitCode(), evaluate.out() + evaluate.err());
        Path evaluation = figures.resolveSibling("EVALUATION.md");
        List<String> storeAudit = List.of(PROJECT.resolve("scripts/audit_store.py").toString(), db.toString(),
                "--report", db.getParent().resolve("report/index.html").toString(), "--compare", compareOut.toString(),
                "--evaluation", evaluation.toString());
        String store = python(storeAudit);
        assertAgrees(store);
        // Table 2: two cells, predict and update
        assertTrue(store.matches("(?s).*evaluation: ([4-9]|\\d{2,}) Wilson intervals checked.*"), store);
        assertWilsonMisprintIsCaught(storeAudit, evaluation);
        assertTrue(store.contains("report: 2 cells checked of 2"), store);
        assertTrue(store.matches("(?s).*compare .*: (\\d{2,}) means checked.*"), "compare's table was read: " + store);
        // every row's p and verdict (9 metrics, 10 runs a side), the two cells' separation of their misses
        assertTrue(store.matches("(?s).*compare .*: 9 p-values, 9 verdicts, \\d+ bootstrap bounds checked.*"), store);
        assertTrue(store.contains("report: 2 miss separations checked (2 with 10 runs a side)"), store);
        assertTrue(store.matches("(?s).*report: \\d{3,} bootstrap interval checks.*"), store);

        // the rtsj-atomic runs as if a second matrix had made them at --time-scale 0.5, and five javase runs on an
        // updated JVM: the report names them apart, and the audit takes compare's sides by the report's row names
        Path labelled = Files.copy(db, db.resolveSibling("labelled.db"));
        String version;
        String profile;
        try (Connection c = DriverManager.getConnection("jdbc:sqlite:" + labelled); Statement s = c.createStatement()) {
            s.execute("INSERT INTO matrices SELECT matrix_id || '-2', machine_id, command, order_seed, started_at,"
                    + " json_set(spec_json, '$.timeScale', 0.5) FROM matrices");
            s.execute("UPDATE runs SET matrix_id = matrix_id || '-2' WHERE engine = 'rtsj-atomic'");
            s.execute("UPDATE runs SET runtime_version = runtime_version || '-updated' WHERE run_key IN"
                    + " (SELECT run_key FROM runs WHERE engine = 'javase' ORDER BY run_key LIMIT 5)");
            try (ResultSet rs = s.executeQuery("SELECT runtime_version, profile FROM runs WHERE engine = 'rtsj-atomic' LIMIT 1")) {
                assertTrue(rs.next());
                version = rs.getString(1);
                profile = rs.getString(2);
            }
        }
        Path labelledReport = dir.resolve("labelled-report");
        assertEquals(0, Fixtures.cli("report", "--db", labelled.toString(), "--out", labelledReport.toString(), "--no-export").exitCode());
        String name = profile == null || profile.isEmpty() ? runtime : runtime + "/" + profile;
        Fixtures.CliResult labelledCompare = Fixtures.cli("compare", "--db", labelled.toString(),
                "--a", name + " / javase [" + version + "] [time scale 0.1]", "--b", name + " / rtsj-atomic [" + version + "] [time scale 0.5]");
        assertEquals(0, labelledCompare.exitCode(), labelledCompare.out() + labelledCompare.err());
        Path labelledCompareOut = dir.resolve("labelled-compare.txt");
        Files.writeString(labelledCompareOut, labelledCompare.out());
        String audit = python(List.of(PROJECT.resolve("scripts/audit_store.py").toString(), labelled.toString(),
                "--report", labelledReport.resolve("index.html").toString(), "--compare", labelledCompareOut.toString()));
        assertAgrees(audit);
        assertTrue(audit.contains("report: 3 cells checked of 3"), audit);
        assertTrue(audit.matches("(?s).*compare .*: (\\d{2,}) means checked.*"), "compare's table was read: " + audit);

        // three javase runs from a store that kept no runtime version: the report pooled them with the seven on the
        // version it knows, and the audit, which groups by version, found a cell of ten runs where it had seven; they
        // are a group of their own ("[version unknown]") in both
        Path untold = Files.copy(db, db.resolveSibling("untold.db"));
        try (Connection c = DriverManager.getConnection("jdbc:sqlite:" + untold); Statement s = c.createStatement()) {
            s.execute("UPDATE runs SET runtime_version = NULL WHERE run_key IN"
                    + " (SELECT run_key FROM runs WHERE engine = 'javase' ORDER BY run_key LIMIT 3)");
        }
        Path untoldReport = dir.resolve("untold-report");
        assertEquals(0, Fixtures.cli("report", "--db", untold.toString(), "--out", untoldReport.toString(), "--no-export").exitCode());
        String untoldAudit = python(List.of(PROJECT.resolve("scripts/audit_store.py").toString(), untold.toString(),
                "--report", untoldReport.resolve("index.html").toString()));
        assertAgrees(untoldAudit);
        assertTrue(untoldAudit.contains("report: 3 cells checked of 3"), untoldAudit);
        assertTrue(Files.readString(untoldReport.resolve("index.html")).contains("/ javase [version unknown]"), "the group is named");
    }

    /**
     * scripts/audit_explain.py: explain's attribution of each run's missed jobs, as explain --json prints it and as
     * the store keeps it (attributions, cause.* metrics), equals its recomputation from the job lines and the JFR
     * recording by docs/FORMATS.md's definitions.
     */
    private void assertExplainAgrees(Path db, List<String> runDirs) throws Exception {
        List<String> args = new ArrayList<>(List.of(PROJECT.resolve("scripts/audit_explain.py").toString(), "--db", db.toString()));
        for (String runDir : runDirs) {
            Fixtures.CliResult explain = Fixtures.cli("explain", "--json", runDir);
            assertEquals(0, explain.exitCode(), explain.out() + explain.err());
            Path json = Files.createTempFile(dir, "explain", ".json");
            Files.writeString(json, explain.out());
            args.addAll(List.of("--explain", json.toString()));
        }
        String out = python(args);
        assertAgrees(out);
        assertTrue(out.matches("(?s).*\\(events: jfr, [1-9]\\d*\\).*"), "the recordings were read: " + out);
    }

    /**
     * The audit's Wilson check can fail: the document with one bound off by a unit of its last digit printed (a
     * hundredth of a percent) is a disagreement, named with its line.
     */
    private void assertWilsonMisprintIsCaught(List<String> storeAudit, Path evaluation) throws Exception {
        String text = Files.readString(evaluation);
        java.util.regex.Matcher m = java.util.regex.Pattern.compile("\\| (\\d+\\.\\d{2}) \\[(\\d+\\.\\d{2}), (\\d+\\.\\d{2})\\] % \\|")
                .matcher(text);
        assertTrue(m.find(), "no Wilson interval in " + text);
        String high = m.group(3);
        String wrong = new java.math.BigDecimal(high).add(new java.math.BigDecimal("0.01")).toPlainString();
        Path misprinted = dir.resolve("misprinted.md");
        Files.writeString(misprinted, text.substring(0, m.start(3)) + wrong + text.substring(m.end(3)));
        List<String> args = new ArrayList<>(storeAudit);
        args.set(args.size() - 1, misprinted.toString());
        Process p = new ProcessBuilder(prepend("python3", args)).redirectErrorStream(true).start();
        String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        assertTrue(p.waitFor(120, TimeUnit.SECONDS), "the audit did not finish in 120 s");
        assertEquals(1, p.exitValue(), out);
        assertTrue(out.matches("(?s).*DISAGREE evaluation misprinted\\.md line \\d+: .*, " + wrong + "\\] %.*1 disagree.*"), out);
    }

    private static List<String> prepend(String first, List<String> rest) {
        List<String> out = new ArrayList<>(List.of(first));
        out.addAll(rest);
        return out;
    }

    private static void assertAgrees(String out) {
        assertTrue(out.contains(", 0 disagree,"), out);
        assertTrue(!out.contains(" 0 numbers compared"), out);
    }

    /**
     * The matrix runs {@code java -cp <workload jar>}: a jar whose manifest puts this test's class path
     * (the workload and the engines it loads, built by the reactor) behind it.
     */
    private static void workloadJarOfThisClassPath(Path jar) throws IOException {
        StringBuilder cp = new StringBuilder();
        for (String entry : System.getProperty("java.class.path").split(File.pathSeparator)) {
            cp.append(Path.of(entry).toUri()).append(' ');
        }
        Manifest mf = new Manifest();
        mf.getMainAttributes().put(Attributes.Name.MANIFEST_VERSION, "1.0");
        mf.getMainAttributes().put(Attributes.Name.CLASS_PATH, cp.toString().strip());
        try (OutputStream out = Files.newOutputStream(jar); JarOutputStream j = new JarOutputStream(out, mf)) {
            j.flush();
        }
    }

    /** Runs python3 with {@code args}; its output, failing the test when it exits other than 0. */
    private String python(List<String> args) throws Exception {
        List<String> cmd = new ArrayList<>(List.of("python3"));
        cmd.addAll(args);
        Path log = Files.createTempFile(dir, "audit", ".txt");
        Process p = new ProcessBuilder(cmd).redirectErrorStream(true).redirectOutput(log.toFile()).start();
        assertTrue(p.waitFor(120, TimeUnit.SECONDS), "the audit did not finish in 120 s");
        String out = Files.readString(log, StandardCharsets.UTF_8);
        assertEquals(0, p.exitValue(), out);
        return out;
    }

    private static boolean python3Available() {
        for (String d : System.getenv().getOrDefault("PATH", "").split(File.pathSeparator)) {
            if (Files.isExecutable(Path.of(d, "python3"))) {
                return true;
            }
        }
        return false;
    }
}
