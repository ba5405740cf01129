package org.jmclbench.tooling.attribution;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class ExplainCommandTest {

    /** A runner-style folder: runs/<key>/recording.jfr beside the run tree, built from the jdk17 fixture. */
    static Path runnerStyleRun(Path root, boolean withClock) throws Exception {
        Path fx = Fixtures.dir("jdk17");
        Path key = root.resolve("runs/ab12");
        Path leaf = key.resolve("local/nocov/400/QueueTest/1");
        Files.createDirectories(leaf);
        Files.copy(fx.resolve("recording.jfr"), key.resolve("recording.jfr"));
        Files.copy(fx.resolve("jobs.txt"), leaf.resolve("odoData.txt"));
        Files.writeString(leaf.resolve("laserData.txt"), "# index release_ns start_ns end_ns deadline_ns outcome cpu_ns\n");
        RunClock c = RunClock.fromText(fx.resolve("clock.txt"));
        String clock = withClock ? ", \"clock\": {\"runStartEpochNs\": " + c.runStartEpochNs() + ", \"runStartNanoTime\": "
                + c.runStartNanoTime() + ", \"jvmStartEpochMs\": " + c.jvmStartEpochMs() + "}" : "";
        Files.writeString(leaf.resolve("summary.json"), "{\"schema\": \"jmclbench-run/1\", \"status\": \"complete\", "
                + "\"parameters\": {\"policy\": \"queue\", \"particles\": 400, \"load\": {\"scenario\": \"alloc\"}}, "
                + "\"environment\": {\"runtime\": {\"vmName\": \"OpenJDK 64-Bit Server VM\", \"version\": \"17\", \"gcNames\": [\"Copy\"]}}"
                + clock + "}");
        return key;
    }

    private static String[] run(String... args) {
        org.jmclbench.tooling.Fixtures.CliResult r = org.jmclbench.tooling.Fixtures.cli(args);
        return new String[] {Integer.toString(r.exitCode()), r.out(), r.err()};
    }

    @Test
    void explainsEachLateJobOfARunFromTheRecordingBesideItsTree(@TempDir Path tmp) throws Exception {
        Path key = runnerStyleRun(tmp, true);
        String[] r = run("explain", "--limit", "0", key.toString());
        assertEquals("0", r[0], r[2]);
        String out = r[1];
        assertTrue(out.contains("events:  JFR " + key.resolve("recording.jfr")), out);
        assertTrue(out.contains("load alloc"), out);
        assertTrue(out.matches("(?s).*\nmissed or late: (\\d+) of \\d+ jobs \\(\\1 late\\)\n.*"), "queue: every one late\n" + out);
        assertTrue(out.matches("(?s).*causes:  .*gc \\d+ \\[\\d+\\].*"), out);
        assertTrue(out.matches("(?s).*\\npredict +40 late .*compute 4\\d\\.\\d ms.*"), "the slow job is compute:\n" + out);
        // The leaf given directly finds the same recording five levels up.
        String[] leaf = run("explain", "--json", key.resolve("local/nocov/400/QueueTest/1").toString());
        assertEquals("0", leaf[0], leaf[2]);
        assertTrue(leaf[1].contains("\"kind\" : \"gc\""), leaf[1]);
        // So does a folder between the two, which holds that one run.
        String[] runtime = run("explain", "--limit", "0", key.resolve("local").toString());
        assertEquals("0", runtime[0], runtime[2]);
        assertTrue(runtime[1].contains("events:  JFR " + key.resolve("recording.jfr")), runtime[1]);
    }

    @Test
    void theJobsAreCountedByHowTheyMissedInTheReportsWords() {
        JobAttribution dropped = new JobAttribution("predict", 1, "skipped", 0, 1, null, java.util.List.of());
        JobAttribution aborted = new JobAttribution("update", 2, "terminated", 0, 1, null, java.util.List.of());
        JobAttribution late = new JobAttribution("update", 3, "late", 0, 1, null, java.util.List.of());
        assertEquals(" (2 dropped, 1 aborted, 1 late)",
                ExplainCommand.byOutcome(java.util.List.of(dropped, late, aborted, dropped)));
        assertEquals("", ExplainCommand.byOutcome(java.util.List.of()));
    }

    @Test
    void withoutAClockTheRecordingIsNotUsedAndSaysSo(@TempDir Path tmp) throws Exception {
        Path key = runnerStyleRun(tmp, false);
        String[] r = run("explain", key.toString());
        assertEquals("0", r[0], r[2]);
        assertTrue(r[1].contains("has no \"clock\""), r[1]);
        assertTrue(!r[1].matches("(?s).*causes:  .*gc \\d+.*"), r[1]);
    }

    /** A summary.json that is not one, or a negative --limit or threshold: one line naming the file or option, exit 2. */
    @Test
    void aBadSummaryOrOptionIsOneLineNamingItAndExitTwo(@TempDir Path tmp) throws Exception {
        Path key = runnerStyleRun(tmp, true);
        Path summary = key.resolve("local/nocov/400/QueueTest/1/summary.json");
        String good = Files.readString(summary);
        for (String[] bad : new String[][] {
            {"{\"schema\": \"jmclbench-run/1\",\n  \"status\": complete}\n", summary + ":2: not JSON ("},
            {"{\"schema\": \"jmclbench-run/1\", \"status\": ", summary + ":1: not JSON ("},
            {"", summary + ": not a JSON object"},
            {"[1, 2]\n", summary + ": not a JSON object"},
        }) {
            Files.writeString(summary, bad[0]);
            String[] r = run("explain", key.toString());
            assertEquals("2", r[0], r[1] + r[2]);
            assertEquals(1, r[2].strip().lines().count(), "one line: " + r[2]);
            assertTrue(r[2].startsWith("jmclbench: " + bad[1]), r[2]);
        }
        Files.writeString(summary, good);
        for (String[] bad : new String[][] {{"--limit", "-1"}, {"--os-threshold-us", "-5"}}) {
            String[] r = run("explain", bad[0], bad[1], key.toString());
            assertEquals("2", r[0], r[1] + r[2]);
            assertTrue(r[2].strip().startsWith("jmclbench: " + bad[0] + ": '" + bad[1] + "' is negative"), r[2]);
            assertEquals(1, r[2].strip().lines().count(), r[2]);
            assertEquals("", r[1], "nothing explained");
        }
    }

    @Test
    void jobLinesFewerThanTheSummaryReleasedAreADamagedRunFolder(@TempDir Path tmp) throws Exception {
        // an emptied laserData.txt was explained as a run without update jobs: "0 of N jobs missed"
        Path key = runnerStyleRun(tmp, true);
        Path leaf = key.resolve("local/nocov/400/QueueTest/1");
        Path summary = leaf.resolve("summary.json");
        String good = Files.readString(summary);
        Files.writeString(summary, good.replaceFirst("\\}$", ", \"tasks\": {\"update\": {\"released\": 3}}}"));
        String[] r = run("explain", key.toString());
        assertEquals("2", r[0], r[1] + r[2]);
        assertEquals("jmclbench: " + leaf.resolve("laserData.txt") + ": 0 job lines, but summary.json says 3 update jobs"
                + " were released (a damaged run folder)", r[2].strip());
        assertEquals("", r[1], "nothing explained");
        Files.writeString(summary, good.replaceFirst("\\}$", ", \"tasks\": {\"update\": {\"released\": 0}}}"));
        assertEquals("0", run("explain", key.toString())[0], "the counts agree");
    }

    @Test
    void aFolderWithoutARunIsBadInput(@TempDir Path tmp) {
        String[] r = run("explain", tmp.toString());
        assertEquals("2", r[0]);
        assertTrue(r[2].startsWith("jmclbench: " + tmp + ": no run folder"), r[2]);
        assertEquals(1, r[2].strip().lines().count());
    }

    /** A recording by another name (a run started by hand with its own -XX:StartFlightRecording) is named by --events. */
    @Test
    void eventsNamesARecordingThatIsNotFoundByName(@TempDir Path tmp) throws Exception {
        Path key = runnerStyleRun(tmp, true);
        Path mine = tmp.resolve("mine.jfr");
        Files.move(key.resolve("recording.jfr"), mine);
        String[] none = run("explain", key.toString());
        assertEquals("0", none[0], none[2]);
        assertTrue(none[1].contains("events:  none (no recording.jfr or gc.log in the run folder or its parents; "
                + "--events names another): only os, queued, preemption and compute can be told\n"), none[1]);
        String[] given = run("explain", "--events", mine.toString(), key.toString());
        assertEquals("0", given[0], given[2]);
        assertTrue(given[1].matches("(?s).*events:  JFR " + java.util.regex.Pattern.quote(mine.toString())
                + " \\([1-9]\\d* events\\)\n.*"), given[1]);
        assertTrue(given[1].matches("(?s).*causes:  .*gc \\d+ \\[\\d+\\].*"), given[1]);
        String[] missing = run("explain", "--events", tmp.resolve("nosuch.jfr").toString(), key.toString());
        assertEquals("2", missing[0], missing[1] + missing[2]);
        assertEquals("jmclbench: --events: " + tmp.resolve("nosuch.jfr") + ": no such file", missing[2].strip());
    }

    /** A text that is neither a recording nor a GC log was read as a GC log of no events: explained without them, exit 0. */
    @Test
    void eventsThatAreNoGcLogAreRefusedWhileAGcLogWithoutPausesIsRead(@TempDir Path tmp) throws Exception {
        Path key = runnerStyleRun(tmp, true);
        Files.delete(key.resolve("recording.jfr"));
        Path notes = tmp.resolve("notes.txt");
        Files.writeString(notes, "run 3 was slow\nsee the recording\n");
        String[] wrong = run("explain", "--events", notes.toString(), key.toString());
        assertEquals("2", wrong[0], wrong[1] + wrong[2]);
        assertEquals("jmclbench: --events: " + notes + ": neither a JFR recording (named .jfr) nor a GC log"
                + " (no line of it is one a GC log writes)", wrong[2].strip());
        assertEquals("", wrong[1], "nothing explained");
        // named .jfr but no recording: the user's file, not a recording a crashed run left unfinished
        Path fake = Files.writeString(tmp.resolve("notes.jfr"), "not a recording\n");
        String[] notJfr = run("explain", "--events", fake.toString(), key.toString());
        assertEquals("2", notJfr[0], notJfr[1] + notJfr[2]);
        assertEquals("jmclbench: --events: " + fake + ": not a JFR recording JFR can read", notJfr[2].strip());
        assertEquals("", notJfr[1], "nothing explained");
        // What --gc-log wrote for a -p 10 run (JDK 17): one safepoint, no pause; and a log of a run
        // in which nothing stopped the world, which stays empty.
        Path quiet = tmp.resolve("quiet.log");
        Files.writeString(quiet, "[1.043s][87624488262750ns][info][safepoint] Safepoint \"Cleanup\", Time since last:"
                + " 1000103065 ns, Reaching safepoint: 7423 ns, Cleanup: 67807 ns, At safepoint: 2374 ns, Total: 77604 ns\n");
        Path empty = Files.createFile(tmp.resolve("empty.log"));
        for (Path log : new Path[] {quiet, empty}) {
            String[] read = run("explain", "--limit", "0", "--events", log.toString(), key.toString());
            assertEquals("0", read[0], read[2]);
            assertTrue(read[1].matches("(?s).*events:  GC log " + java.util.regex.Pattern.quote(log.toString())
                    + " \\(\\d events\\)\n.*"), read[1]);
        }
    }
}
