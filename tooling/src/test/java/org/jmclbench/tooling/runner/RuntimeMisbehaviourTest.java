package org.jmclbench.tooling.runner;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.sql.Connection;
import java.sql.DriverManager;
import java.sql.ResultSet;
import java.sql.Statement;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

import org.jmclbench.tooling.Fixtures;
import org.junit.jupiter.api.Test;

/**
 * Runtimes under test that misbehave in ways MatrixIsolationTest's do not: each is that run's
 * recorded failure (nothing of it stored as a result), never the runner's, and the matrix goes on.
 */
class RuntimeMisbehaviourTest extends FakeJvmHome {

    /** A run's row: status, failure, stderr tail, summary kept, metrics kept. */
    record Row(String status, String failure, String tail, String summary, int metrics) {
    }

    private Map<String, Row> matrix(String... modes) throws Exception {
        List<String> args = new ArrayList<>(List.of("matrix", "--datasets", "tiny", "--particles", "100",
                "--timeout", "15", "--db", db.toString(), "--java", fake.toString()));
        for (int i = 0; i < modes.length; i++) {
            args.add("--java");
            args.add(Fixtures.fakeJava(dir, modes[i], modes[i], 0, null, 22 + i).toString());
        }
        Fixtures.CliResult r = Fixtures.cli(args.toArray(String[]::new));
        assertEquals(0, r.exitCode(), r.out() + r.err());
        Map<String, Row> rows = new HashMap<>();
        try (Connection c = DriverManager.getConnection("jdbc:sqlite:" + db); Statement s = c.createStatement();
             ResultSet rs = s.executeQuery("SELECT runtime, status, failure, stderr_tail, summary_json,"
                     + " (SELECT count(*) FROM metrics m WHERE m.run_key = runs.run_key) FROM runs")) {
            while (rs.next()) {
                rows.put(rs.getString(1), new Row(rs.getString(2), rs.getString(3), rs.getString(4), rs.getString(5), rs.getInt(6)));
            }
        }
        assertEquals(modes.length + 1, rows.size(), rows.toString());
        assertEquals("ok", rows.get("fake-21").status(), "the well-behaved runtime's run is made: " + rows);
        return rows;
    }

    /**
     * A crashed aot training is the failure of the run it trained for, not of the runtime for the
     * rest of the matrix: the next repetition trains again (the crash was kept, and one failed every
     * repetition of that runtime and policy).
     */
    @Test
    void aCrashedAotTrainingFailsOnlyTheRunItTrainedFor() throws Exception {
        Path flaky = Fixtures.fakeJava(dir, "aotflaky", "aotflaky", 0, null, 25);
        Fixtures.CliResult r = Fixtures.cli("matrix", "--datasets", "tiny", "--particles", "100", "--repeat", "2",
                "--profiles", "aot", "--timeout", "15", "--db", db.toString(), "--java", flaky.toString());
        assertEquals(0, r.exitCode(), r.out() + r.err());
        // the first run (either repetition: the order is shuffled) met the crash, the other trained again
        List<String> outcomes = new ArrayList<>(Fixtures.columns(db, "SELECT repetition, status || ': ' || coalesce(failure, '')"
                + " FROM runs").values());
        outcomes.sort(null);
        assertEquals(2, outcomes.size(), outcomes.toString());
        assertTrue(outcomes.get(0).startsWith("failed: aot: training run failed (exit code 139: killed by SIGSEGV"), outcomes.toString());
        assertEquals("ok: ", outcomes.get(1), outcomes.toString());
    }

    /**
     * Gigabytes of stderr: the runner reads only the end of stderr.txt for the run's tail (it read
     * the whole file, and a 3 GB one ended the runner with OutOfMemoryError, losing the matrix).
     */
    @Test
    void aRuntimeFloodingItsStderrIsItsFailureAndTheRunnerReadsOnlyTheTail() throws Exception {
        Row flood = matrix("flood").get("fake-22");
        assertEquals("failed", flood.status(), flood.toString());
        assertEquals("exit code 1: jmclbench: failure: flooded its stderr", flood.failure());
        assertTrue(flood.tail().length() <= ForkedRun.STDERR_TAIL_CHARS, "" + flood.tail().length());
        assertNull(flood.summary());
    }

    /**
     * A runaway summary.json of 3 GB (sparse, after a good summary): read whole, it ended the runner
     * with OutOfMemoryError; now the run's failure, the matrix going on.
     */
    @Test
    void aRunawaySummaryIsGarbageAndNotReadWhole() throws Exception {
        Row r = matrix("hugesummary").get("fake-22");
        assertEquals("failed", r.status(), r.toString());
        assertEquals("garbage output: summary.json is 3221225472 bytes, more than a summary's " + ForkedRun.MAX_SUMMARY_BYTES,
                r.failure());
        assertNull(r.summary());
    }

    /**
     * A job file of 3 GB ending in one line without an end (sparse): read whole, it ended the runner
     * with OutOfMemoryError; now refused at its first overlong line, the run's failure.
     */
    @Test
    void aRunawayJobFileIsGarbageAndNotReadWhole() throws Exception {
        Row r = matrix("hugejobs").get("fake-22");
        assertEquals("failed", r.status(), r.toString());
        assertTrue(r.failure().startsWith("garbage output: ") && r.failure().endsWith("odoData.txt:12: a line longer than "
                + org.jmclbench.tooling.store.RunFolderIngest.MAX_LINE_CHARS + " characters"), r.failure());
        assertNull(r.summary());
    }

    /**
     * A job file, or a file of one row per odometry time, that goes on far past the jobs summary.json
     * says were released (a runtime looping on its writer): read no further than one row past the
     * count, not whole (a multi-GB file of short lines would take the runner's memory), and the run's failure.
     */
    @Test
    void rowsFarPastTheReleasedJobsAreGarbageReadNoFurtherThanOnePast() throws Exception {
        Map<String, Row> rows = matrix("manyjobs", "manyrows");
        Row jobs = rows.get("fake-22");
        assertEquals("failed", jobs.status(), jobs.toString());
        assertTrue(jobs.failure().endsWith("odoData.txt: more than 10 job lines, but summary.json says 10 predict jobs were released"),
                jobs.failure());
        Row position = rows.get("fake-23");
        assertEquals("failed", position.status(), position.toString());
        assertTrue(position.failure().endsWith("position.txt: more than 10 rows, one an odometry time, but summary.json says 10"
                + " predict jobs were released"), position.failure());
    }

    /**
     * A good run of a JVM 10 whose GC log (the run's event capture) ends in a 64 MB line without an
     * end: its attribution read the log whole (a multi-GB one ended the runner with OutOfMemoryError)
     * and, finding no event in it, stored the run's misses as explained without a pause. Now the run
     * stands, without attribution (no cause metric, no attribution row), and the runner says why.
     */
    @Test
    void aRunawayGcLogLeavesTheRunWithoutAttributionNotTheRunnerDead() throws Exception {
        String err = runWithoutAttribution("runawaygclog", 10);
        assertTrue(err.matches("(?s).*: no attribution: [^\\n]*gc\\.log:2: a line longer than "
                + org.jmclbench.tooling.cli.BoundedLineReader.MAX_LINE_CHARS + " characters\\n.*"), err);
    }

    /**
     * A good run of a JVM 11+ whose recording JFR cannot read: it was attributed from its job lines
     * alone and stored as a run without capture ({@code cause.events} 0), its pauses told as other
     * causes. Now the run stands without attribution.
     */
    @Test
    void anUnreadableRecordingOfAGoodRunLeavesItWithoutAttribution() throws Exception {
        String err = runWithoutAttribution("badrecording", 22);
        assertTrue(err.matches("(?s).*: no attribution: JFR [^\\n]*recording\\.jfr unreadable[^\\n]*\\n.*"), err);
    }

    /** Runs a good runtime and {@code mode}'s; that run is ok, without attribution. Returns the matrix's stderr. */
    private String runWithoutAttribution(String mode, int major) throws Exception {
        Path runtime = Fixtures.fakeJava(dir, mode, mode, 0, null, major);
        Fixtures.CliResult r = Fixtures.cli("matrix", "--datasets", "tiny", "--particles", "100", "--timeout", "15",
                "--db", db.toString(), "--java", fake.toString(), "--java", runtime.toString());
        assertEquals(0, r.exitCode(), r.out() + r.err());
        try (Connection c = DriverManager.getConnection("jdbc:sqlite:" + db); Statement s = c.createStatement();
             ResultSet rs = s.executeQuery("SELECT runtime, status,"
                     + " (SELECT count(*) FROM metrics m WHERE m.run_key = runs.run_key AND m.metric LIKE 'cause.%'),"
                     + " (SELECT count(*) FROM attributions a WHERE a.run_key = runs.run_key),"
                     + " (SELECT count(*) FROM metrics m WHERE m.run_key = runs.run_key) FROM runs WHERE runtime = 'fake-"
                     + major + "'")) {
            assertTrue(rs.next(), "the run is recorded");
            assertEquals("ok", rs.getString(2), "the run itself is good");
            assertEquals(0, rs.getInt(3), "no cause metric");
            assertEquals(0, rs.getInt(4), "no attribution row");
            assertTrue(rs.getInt(5) > 0, "its own metrics are stored");
        }
        return r.err();
    }

    /**
     * A summary.json that claims jobs its job files do not hold (20 predict jobs released for 10
     * lines; a job file cut to 5 of its 10): the run was recorded ok with the summary's counts,
     * which no job backs; now failed, naming the file and both counts, nothing of it stored.
     */
    @Test
    void aSummaryClaimingJobsTheJobFilesDoNotHoldIsGarbageNotAResult() throws Exception {
        Map<String, Row> rows = matrix("overclaim", "shortjobs");
        for (String[] c : new String[][] {{"fake-22", "10 job lines, but summary.json says 20 predict jobs were released"},
                {"fake-23", "5 job lines, but summary.json says 10 predict jobs were released"}}) {
            Row r = rows.get(c[0]);
            assertEquals("failed", r.status(), r.toString());
            assertTrue(r.failure().startsWith("garbage output: ") && r.failure().contains("odoData.txt: " + c[1]), r.failure());
            assertNull(r.summary());
            assertEquals(0, r.metrics(), "no metric of a failed run");
        }
    }

    /**
     * A runtime that ends itself by SIGTERM, SIGINT or SIGHUP (a JVM's own shutdown, a wrapper script
     * signalling its group) while the runner is not stopping: each run was read as the user's Ctrl-C,
     * ending the whole matrix with exit 1 and the runs after it never made; now each is that run's
     * failure naming the signal, and the matrix goes on (exit 0, as for any failed run).
     */
    @Test
    void aRuntimeEndingItselfBySignalIsItsFailureNotAnInterruption() throws Exception {
        Map<String, Row> rows = matrix("sigterm", "sigint", "sighup");
        for (String[] c : new String[][] {{"fake-22", "exit code 143: killed by SIGTERM"},
                {"fake-23", "exit code 130: killed by SIGINT"}, {"fake-24", "exit code 129: killed by SIGHUP"}}) {
            Row r = rows.get(c[0]);
            assertEquals("failed", r.status(), r.toString());
            assertEquals(c[1], r.failure());
            assertNull(r.summary());
            assertEquals(0, r.metrics(), "no metric of a failed run");
        }
    }

    /**
     * A runtime that exits 0 with a good run but leaves a child running (holding its output open):
     * the child was re-parented and lived on beside the following runs, which must never overlap;
     * now everything left in the run's session is killed when the run ends.
     */
    @Test
    void aChildThatOutlivesTheRuntimeIsKilledWhenTheRunEnds() throws Exception {
        String mark = Fixtures.hangMark(dir);
        try {
            Row orphan = matrix("orphan").get("fake-22");
            assertEquals("ok", orphan.status(), "the run itself completed: " + orphan);
            assertEquals(List.of(), survivors(mark), "a child of the run outlived the matrix");
        } finally {
            survivors(mark).forEach(ProcessHandle::destroyForcibly);
        }
    }

    private static List<ProcessHandle> survivors(String mark) {
        return ProcessHandle.allProcesses().filter(p -> p.info().commandLine().orElse("").contains(mark)).toList();
    }
}
