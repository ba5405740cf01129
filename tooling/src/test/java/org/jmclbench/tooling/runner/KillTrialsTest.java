package org.jmclbench.tooling.runner;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.sql.Connection;
import java.sql.DriverManager;
import java.sql.ResultSet;
import java.sql.Statement;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Random;
import java.util.concurrent.TimeUnit;
import java.util.stream.Stream;

import org.jmclbench.tooling.Fixtures;
import org.jmclbench.tooling.store.RunRow;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The runner itself is killed with SIGKILL at a random point of a matrix (after a random number of
 * committed runs, then a random part of the next run); rerunning the same command must finish it with
 * every run present exactly once and the runs committed before the kill untouched. A few trials:
 * bench/kill-trials.sh runs many, on real runs.
 */
class KillTrialsTest {

    /** Runs in the matrix: 2 runtimes x 2 policies x 3 sizes. */
    private static final int PLANNED = 12;

    @TempDir
    Path dir;

    @Test
    void aMatrixKilledAtRandomPointsResumesWithEveryRunOnce() throws Exception {
        Fixtures.home(dir);
        Random random = new Random(20);
        for (int trial = 1; trial <= 3; trial++) {
            trial(dir.resolve("t" + trial), random.nextInt(PLANNED - 1), random.nextInt(1000));
        }
    }

    /** Kills the matrix after {@code committed} runs are in its store and {@code laterMs} more. */
    private void trial(Path t, int committed, int laterMs) throws Exception {
        Path db = t.resolve("out/results.db");
        List<String> cmd = Fixtures.childCli(dir,
                "matrix", "--java", Fixtures.fakeJava(dir, "a", "ok", 0.3, null, 17).toString(),
                "--java", Fixtures.fakeJava(dir, "b", "ok", 0.3, null, 21).toString(),
                "--policies", "skip,terminate", "--particles", "100,200,300", "--datasets", "tiny",
                "--db", db.toString());
        Files.createDirectories(t);
        Path log1 = t.resolve("first.log");
        Process first = new ProcessBuilder(cmd).redirectErrorStream(true).redirectOutput(log1.toFile()).start();
        // wait (generously: the machine is shared) until enough runs are committed, then kill -9
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(240);
        while (rows(db).size() < committed && System.nanoTime() < deadline && first.isAlive()) {
            Thread.sleep(50);
        }
        Thread.sleep(laterMs);
        // a runner that ended first (a fast machine) makes this trial a plain rerun: the checks hold as well
        String when = t + ": killed after " + committed + " runs and " + laterMs + " ms" + (first.isAlive() ? "" : " (had ended)");
        first.destroyForcibly(); // SIGKILL: no shutdown hook runs
        assertTrue(first.waitFor(30, TimeUnit.SECONDS), when);
        assertEquals("ok", integrity(db), when + ": the store as the kill left it");
        Map<String, String> before = rows(db);

        Path log2 = t.resolve("second.log");
        Process second = new ProcessBuilder(cmd).redirectErrorStream(true).redirectOutput(log2.toFile()).start();
        assertTrue(second.waitFor(300, TimeUnit.SECONDS), when + ": the resumed matrix did not finish");
        String out2 = Files.readString(log2);
        assertEquals(0, second.exitValue(), when + ": " + out2);
        assertTrue(out2.contains(before.size() + " already in"), when + ": " + out2);

        Map<String, String> after = rows(db);
        assertEquals(PLANNED, after.size(), when);
        assertEquals("ok", integrity(db), when);
        try (Connection c = DriverManager.getConnection("jdbc:sqlite:" + db); Statement s = c.createStatement();
             ResultSet rs = s.executeQuery("SELECT count(*), count(DISTINCT runtime || profile || policy || particles || repetition),"
                     + " sum(status = 'ok') FROM runs")) {
            assertTrue(rs.next());
            assertEquals(PLANNED, rs.getInt(1), when);
            assertEquals(PLANNED, rs.getInt(2), when + ": no configuration twice");
            assertEquals(PLANNED, rs.getInt(3), when + ": all ok: " + out2);
        }
        for (Map.Entry<String, String> e : before.entrySet()) {
            assertEquals(e.getValue(), after.get(e.getKey()), when + ": a run committed before the kill was redone");
        }
        // one complete run folder per run, no leftovers of the killed run
        for (String key : after.keySet()) {
            try (Stream<Path> s = Files.walk(db.getParent().resolve("runs").resolve(key))) {
                List<Path> leaves = s.filter(p -> p.getFileName().toString().equals("summary.json")).toList();
                assertEquals(1, leaves.size(), when + ": " + key + ": " + leaves);
            }
            try (Stream<Path> s = Files.walk(db.getParent().resolve("runs").resolve(key))) {
                assertTrue(s.noneMatch(p -> p.getFileName().toString().endsWith(".partial")), when + ": " + key);
            }
        }
        try (Stream<Path> s = Files.list(db.getParent().resolve("runs"))) {
            assertEquals(PLANNED, s.filter(Files::isDirectory).count(), when + ": one folder per run");
        }
    }

    /**
     * A runner stopped with SIGTERM (or Ctrl-C) kills its run in progress from its shutdown hook; that
     * run ended by the runner's hand and must not be recorded as the runtime's failure (which a rerun
     * would keep as final), but be run again by the rerun.
     */
    @Test
    void aRunnerStoppedMidRunRecordsNoFailureForTheRunItStopped() throws Exception {
        List<String> cmd = gatedMatrix();
        Process runner = startAndAwaitTheRun(cmd);
        runner.destroy(); // SIGTERM to the runner only
        assertTrue(runner.waitFor(60, TimeUnit.SECONDS));
        assertEquals(Map.of(), rows(gatedDb()), "the stopped run is not recorded: " + firstErr());
        resumesWithTheRunOk(cmd);
    }

    /**
     * The run's process ended by SIGTERM from outside while the runner goes on (the run leads its own
     * session, so this is no Ctrl-C of the runner's terminal): the runtime's failure, recorded as
     * such; it ended the matrix as an interruption, exit 1, with nothing recorded.
     */
    @Test
    void aRunEndedBySigtermFromOutsideIsTheRuntimesFailure() throws Exception {
        List<String> cmd = gatedMatrix();
        Process runner = startAndAwaitTheRun(cmd);
        runner.descendants().toList().forEach(ProcessHandle::destroy); // SIGTERM to the run only
        assertTrue(runner.waitFor(60, TimeUnit.SECONDS));
        String err = firstErr();
        assertEquals(0, runner.exitValue(), err);
        assertEquals(Map.of("failed", "exit code 143: killed by SIGTERM"), statuses(gatedDb()), err);
    }

    /**
     * A system shutdown's SIGTERM reaches every process, and the run may die of it before the runner's
     * shutdown hook has begun: SIGTERM to the run, then to the runner, is still an interruption,
     * nothing recorded, and the rerun runs it.
     */
    @Test
    void aRunAndItsRunnerBothSignalledIsAnInterruption() throws Exception {
        List<String> cmd = gatedMatrix();
        Process runner = startAndAwaitTheRun(cmd);
        List<ProcessHandle> run = runner.descendants().toList();
        run.forEach(ProcessHandle::destroy);
        for (ProcessHandle h : run) {
            h.onExit().get(30, TimeUnit.SECONDS); // dead before the runner hears of it: the race a shutdown can give
        }
        runner.destroy();
        assertTrue(runner.waitFor(60, TimeUnit.SECONDS));
        assertEquals(Map.of(), rows(gatedDb()), "the run is not recorded: " + firstErr());
        resumesWithTheRunOk(cmd);
    }

    /**
     * The same for the aot profile's training run ended by SIGTERM from outside: the runtime's, the
     * matrix goes on and records the run with the training's failure naming the signal.
     */
    @Test
    void anAotTrainingEndedBySigtermFromOutsideIsTheRuntimes() throws Exception {
        Process runner = new ProcessBuilder(gatedMatrix("--profiles", "aot")).redirectOutput(dir.resolve("first.out").toFile())
                .redirectError(dir.resolve("first.log").toFile()).start();
        try {
            awaitStarted(runner);
            runner.descendants().toList().forEach(ProcessHandle::destroy); // SIGTERM to the training run
            assertTrue(runner.waitFor(60, TimeUnit.SECONDS));
        } finally {
            Files.createFile(dir.resolve("g/open"));
            runner.destroyForcibly();
        }
        String err = firstErr();
        assertEquals(0, runner.exitValue(), err);
        Map<String, String> st = statuses(gatedDb());
        assertEquals(1, st.size(), st.toString());
        // a crash of the runtime's training is its failure, not a feature it lacks
        assertTrue(st.getOrDefault(RunRow.FAILED, "").startsWith("aot: training run failed (exit code 143: killed by SIGTERM)"),
                st.toString());
    }

    /**
     * A runner stopped with SIGTERM while the aot profile trains its cache kills the training run as
     * it kills a run (the training ran on until its own timeout, minutes later), and records nothing.
     */
    @Test
    void aRunnerStoppedMidAotTrainingKillsTheTrainingRun() throws Exception {
        Process runner = new ProcessBuilder(gatedMatrix("--profiles", "aot")).redirectOutput(dir.resolve("first.out").toFile())
                .redirectError(dir.resolve("first.log").toFile()).start();
        List<ProcessHandle> training = List.of();
        try {
            awaitStarted(runner);
            training = runner.descendants().toList();
            assertFalse(training.isEmpty(), "no training run under the runner");
            runner.destroy(); // SIGTERM to the runner only
            assertTrue(runner.waitFor(60, TimeUnit.SECONDS));
            for (ProcessHandle h : training) {
                try {
                    h.onExit().get(30, TimeUnit.SECONDS); // generous: the hook has already waited for the kill
                } catch (java.util.concurrent.TimeoutException e) {
                    throw new AssertionError("the training run (pid " + h.pid() + ") outlived its runner: " + firstErr());
                }
            }
        } finally {
            Files.createFile(dir.resolve("g/open"));
            training.forEach(ProcessHandle::destroyForcibly);
            runner.destroyForcibly();
        }
        assertEquals(Map.of(), rows(gatedDb()), firstErr());
    }

    /** A matrix of one run on a fake runtime that waits at its start until {@code g/open} exists. */
    private List<String> gatedMatrix(String... options) throws Exception {
        Fixtures.home(dir);
        List<String> args = new ArrayList<>(List.of("matrix", "--java",
                Fixtures.fakeJava(dir, "g", "gate", 0, null, 21).toString(), "--particles", "100", "--datasets", "tiny",
                "--timeout", "600", "--db", gatedDb().toString()));
        args.addAll(List.of(options));
        return Fixtures.childCli(dir, args.toArray(new String[0]));
    }

    private Path gatedDb() {
        return dir.resolve("out/results.db");
    }

    /** The first runner's standard error, stripped. */
    private String firstErr() throws Exception {
        return Files.readString(dir.resolve("first.log")).strip();
    }

    /** Starts the first runner (output to first.out, errors to first.log) and waits until its run has started. */
    private Process startAndAwaitTheRun(List<String> cmd) throws Exception {
        Process runner = new ProcessBuilder(cmd).redirectOutput(dir.resolve("first.out").toFile())
                .redirectError(dir.resolve("first.log").toFile()).start();
        awaitStarted(runner);
        return runner;
    }

    /** Waits (generously: the machine is shared) until the gated fake runtime's run has started. */
    private void awaitStarted(Process runner) throws Exception {
        Path started = dir.resolve("g/started");
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(240);
        while (!Files.exists(started) && runner.isAlive() && System.nanoTime() < deadline) {
            Thread.sleep(100);
        }
        assertTrue(Files.exists(started), "the matrix never reached its run");
    }

    private void resumesWithTheRunOk(List<String> cmd) throws Exception {
        Files.createFile(dir.resolve("g/open"));
        Path log = dir.resolve("second.log");
        Process second = new ProcessBuilder(cmd).redirectErrorStream(true).redirectOutput(log.toFile()).start();
        assertTrue(second.waitFor(300, TimeUnit.SECONDS));
        String out = Files.readString(log);
        assertEquals(0, second.exitValue(), out);
        assertTrue(out.contains("0 already in") && out.contains("1 ran (1 ok"), out);
    }

    /** run_key -> started_at of every committed run. */
    private static Map<String, String> rows(Path db) {
        Map<String, String> m = new HashMap<>();
        if (!Files.isRegularFile(db)) {
            return m;
        }
        try (Connection c = DriverManager.getConnection("jdbc:sqlite:" + db); Statement s = c.createStatement()) {
            s.execute("PRAGMA busy_timeout = 5000");
            try (ResultSet rs = s.executeQuery("SELECT run_key, started_at FROM runs")) {
                while (rs.next()) {
                    m.put(rs.getString(1), rs.getString(2));
                }
            }
        } catch (java.sql.SQLException e) {
            return m; // the schema may not exist yet
        }
        return m;
    }

    /** status -> failure of every committed run. */
    private static Map<String, String> statuses(Path db) throws Exception {
        return Fixtures.columns(db, "SELECT status, failure FROM runs");
    }

    /** SQLite's verdict on the whole file ("ok" when none was written yet). */
    private static String integrity(Path db) throws Exception {
        if (!Files.isRegularFile(db)) {
            return "ok";
        }
        try (Connection c = DriverManager.getConnection("jdbc:sqlite:" + db); Statement s = c.createStatement()) {
            s.execute("PRAGMA busy_timeout = 5000");
            try (ResultSet rs = s.executeQuery("PRAGMA integrity_check")) {
                return rs.next() ? rs.getString(1) : "no answer";
            }
        }
    }
}
