package org.jmclbench.tooling.runner;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.sql.Connection;
import java.sql.DriverManager;
import java.sql.ResultSet;
import java.sql.Statement;
import java.util.HashMap;
import java.util.Map;

import org.HdrHistogram.Histogram;
import org.jmclbench.tooling.Fixtures;
import org.jmclbench.tooling.store.RunFolderIngest;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Each run is a separate process: a crash, hang, garbage or OOM is that run's recorded failure, a
 * count the runtime says it cannot run is recorded unsupported with its reason, and the matrix goes on.
 */
class MatrixIsolationTest {

    @TempDir
    Path dir;

    @Test
    void everyKindOfFailureIsRecordedAndTheMatrixGoesOn() throws Exception {
        Fixtures.home(dir);
        String[] modes = {"ok", "crash", "hang", "garbage", "badjson", "oom", "badexit", "wrongrun", "unsupported"};
        java.util.List<String> args = new java.util.ArrayList<>(java.util.List.of("matrix", "--datasets", "tiny",
                "--particles", "100", "--policies", "skip", "--timeout", "15", // generous: the ok runs must not time out on a loaded machine
                "--db", dir.resolve("r/results.db").toString()));
        for (int i = 0; i < modes.length; i++) {
            // distinct majors give distinct runtime names (fake-21, fake-22, ...)
            args.add("--java");
            args.add(Fixtures.fakeJava(dir, modes[i], modes[i], 0, null, 21 + i).toString());
        }
        Fixtures.CliResult r = Fixtures.cli(args.toArray(String[]::new));
        assertEquals(0, r.exitCode(), r.out() + r.err());

        Map<String, String> statusByRuntime = new HashMap<>();
        Map<String, String> failureByRuntime = new HashMap<>();
        try (Connection c = DriverManager.getConnection("jdbc:sqlite:" + dir.resolve("r/results.db"));
             Statement s = c.createStatement();
             ResultSet rs = s.executeQuery("SELECT runtime, status, failure, exit_code, stderr_tail, summary_json, run_dir FROM runs")) {
            while (rs.next()) {
                statusByRuntime.put(rs.getString(1), rs.getString(2));
                failureByRuntime.put(rs.getString(1), rs.getString(3));
                if (rs.getString(2).equals("ok")) {
                    assertNotNull(rs.getString(6));
                    assertTrue(Files.isRegularFile(dir.resolve("r").resolve(rs.getString(7)).resolve("summary.json")));
                } else {
                    assertNull(rs.getString(6), "no summary is kept for a failed run");
                }
            }
        }
        assertEquals(9, statusByRuntime.size(), statusByRuntime.toString());
        assertEquals("ok", statusByRuntime.get("fake-21"));
        assertEquals("failed", statusByRuntime.get("fake-22"));
        assertTrue(failureByRuntime.get("fake-22").contains("SIGSEGV"), failureByRuntime.get("fake-22"));
        assertEquals("timeout", statusByRuntime.get("fake-23"));
        assertEquals("failed", statusByRuntime.get("fake-24"));
        assertTrue(failureByRuntime.get("fake-24").contains("garbage"), failureByRuntime.get("fake-24"));
        assertEquals("failed", statusByRuntime.get("fake-25"));
        assertTrue(failureByRuntime.get("fake-25").contains("summary.json"), failureByRuntime.get("fake-25"));
        assertEquals("failed", statusByRuntime.get("fake-26"));
        assertTrue(failureByRuntime.get("fake-26").contains("out of memory"), failureByRuntime.get("fake-26"));
        assertEquals("failed", statusByRuntime.get("fake-27"));
        assertEquals("failed", statusByRuntime.get("fake-28"));
        assertTrue(failureByRuntime.get("fake-28").contains("describes another run (particles 101, asked 100)"),
                failureByRuntime.get("fake-28"));
        assertEquals("unsupported", statusByRuntime.get("fake-29"));
        assertEquals("--particles 100: the fake VM holds at most 50 particles", failureByRuntime.get("fake-29"));
        assertTrue(r.out().contains("1 ok, 6 failed, 1 timed out, 1 unsupported"), r.out());

        // the hung run's whole process tree was killed
        String mark = Fixtures.hangMark(dir.resolve("hang"));
        assertFalse(ProcessHandle.allProcesses().anyMatch(p -> p.info().commandLine().orElse("").contains(mark)),
                "a process of the hung run survived");

        // the ok run is in metrics, histograms and series, so that the report needs only the database
        try (Connection c = DriverManager.getConnection("jdbc:sqlite:" + dir.resolve("r/results.db"));
             Statement s = c.createStatement()) {
            try (ResultSet rs = s.executeQuery("SELECT m.value FROM metrics m JOIN runs r USING (run_key)"
                    + " WHERE r.runtime = 'fake-21' AND m.task = 'predict' AND m.metric = 'skipped' AND m.stat = 'value'")) {
                assertTrue(rs.next());
                assertEquals(1.0, rs.getDouble(1));
            }
            try (ResultSet rs = s.executeQuery("SELECT h.hdr FROM histograms h JOIN runs r USING (run_key)"
                    + " WHERE r.runtime = 'fake-21' AND h.task = 'predict' AND h.metric = 'taskLatencyNs'")) {
                assertTrue(rs.next());
                Histogram h = RunFolderIngest.decode(rs.getString(1));
                assertEquals(9, h.getTotalCount(), "9 completed predict jobs, the skipped one has no latency");
                assertEquals(2_000_000, h.getMinValue(), 2_000);
            }
            try (ResultSet rs = s.executeQuery("SELECT group_concat(name) FROM series s JOIN runs r USING (run_key)"
                    + " WHERE r.runtime = 'fake-21'")) {
                assertTrue(rs.next());
                String names = rs.getString(1);
                for (String n : new String[] {"taskLatency.predict", "taskLatency.update", "deviation", "trajectory"}) {
                    assertTrue(names.contains(n), names);
                }
            }
            try (ResultSet rs = s.executeQuery("SELECT doctor_json FROM machines")) {
                assertTrue(rs.next());
                assertTrue(rs.getString(1).contains("\"check\":\"rt-throttling\""), rs.getString(1));
            }
        }

        // rerunning resumes: nothing left to run
        Fixtures.CliResult again = Fixtures.cli(args.toArray(String[]::new));
        assertEquals(0, again.exitCode());
        assertTrue(again.out().contains("9 already in"), again.out());
        assertTrue(again.out().contains("0 ran"), again.out());
    }

    /**
     * Exit code 3 is the workload's "unsupported" only with its "jmclbench: unsupported:" line: a JVM
     * that exits 3 by itself (-XX:+ExitOnOutOfMemoryError) failed, and must not be recorded as a
     * limit of the runtime, which no --retry-failed reruns and a capacity search takes for its limit.
     */
    @Test
    void anExitThreeWithoutTheWorkloadsLineIsAFailureNotUnsupported() throws Exception {
        Fixtures.home(dir);
        Path db = dir.resolve("r/results.db");
        Fixtures.CliResult r = Fixtures.cli("matrix", "--java", Fixtures.fakeJava(dir, "oom", "exitoom", 0, null, 21).toString(),
                "--datasets", "tiny", "--particles", "100", "--db", db.toString());
        assertEquals(0, r.exitCode(), r.out() + r.err());
        try (Connection c = DriverManager.getConnection("jdbc:sqlite:" + db); Statement s = c.createStatement();
             ResultSet rs = s.executeQuery("SELECT status, failure FROM runs")) {
            assertTrue(rs.next());
            assertEquals("failed", rs.getString(1), rs.getString(2));
            assertEquals("exit code 3: out of memory (OutOfMemoryError)", rs.getString(2));
        }
    }
}
