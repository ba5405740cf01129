package org.jmclbench.tooling.attribution;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.OutputStream;
import java.io.RandomAccessFile;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;

import org.jmclbench.tooling.cli.BoundedLineReader;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ObjectNode;

/**
 * A runtime under test that left a runaway event capture or job file: explain reads it in bounded
 * memory, and a file past the limits is bad input (exit 2) in one line naming file:line. Limits are
 * shown with 100 KB lines, and memory with a child JVM of a small heap reading sparse or repeated
 * files of tens of MB (each an OutOfMemoryError before: Files.readAllLines, RecordingFile.readAllEvents).
 */
class RunawayCaptureTest {
    private static final String LONG_LINE = "x".repeat(100_000);

    /** The jdk17 fixture's run (runnerStyleRun) with its GC log beside it in place of the recording. */
    private static Path runWithGcLog(Path tmp) throws Exception {
        Path key = ExplainCommandTest.runnerStyleRun(tmp, true);
        Files.delete(key.resolve("recording.jfr"));
        Files.copy(Fixtures.dir("jdk17").resolve("gc.log"), key.resolve("gc.log"));
        return key;
    }

    private static String[] explain(String... args) {
        List<String> all = new ArrayList<>(List.of("explain"));
        all.addAll(List.of(args));
        org.jmclbench.tooling.Fixtures.CliResult r = org.jmclbench.tooling.Fixtures.cli(all.toArray(String[]::new));
        return new String[] {Integer.toString(r.exitCode()), r.out(), r.err()};
    }

    @Test
    void aGcLogLineLongerThanTheLimitIsBadInputNamingFileAndLine(@TempDir Path tmp) throws Exception {
        Path key = runWithGcLog(tmp);
        Path log = key.resolve("gc.log");
        List<String> lines = new ArrayList<>(Files.readAllLines(log));
        lines.add(2, LONG_LINE);
        Files.write(log, lines);
        String[] r = explain(key.toString());
        assertEquals("2", r[0], r[1] + r[2]);
        assertEquals("jmclbench: " + log + ":3: a line longer than " + BoundedLineReader.MAX_LINE_CHARS + " characters\n",
                r[2]);
        // the same file named with --events
        String[] named = explain("--events", log.toString(), key.toString());
        assertEquals("2", named[0], named[1] + named[2]);
        assertTrue(named[2].contains(log + ":3: a line longer than"), named[2]);
        // and one whose first line has no end, refused before it is known to be a GC log at all
        Path endless = tmp.resolve("endless.log");
        Files.writeString(endless, LONG_LINE);
        String[] first = explain("--events", endless.toString(), key.toString());
        assertEquals("2", first[0], first[1] + first[2]);
        assertEquals("jmclbench: --events: " + endless + ":1: a line longer than " + BoundedLineReader.MAX_LINE_CHARS
                + " characters\n", first[2]);
    }

    @Test
    void aJobLineLongerThanTheLimitIsBadInputNamingFileAndLine(@TempDir Path tmp) throws Exception {
        Path key = runWithGcLog(tmp);
        Path odo = key.resolve("local/nocov/400/QueueTest/1/odoData.txt");
        List<String> lines = new ArrayList<>(Files.readAllLines(odo));
        lines.set(1, "1 ".repeat(50_000));
        Files.write(odo, lines);
        String[] r = explain(key.toString());
        assertEquals("2", r[0], r[1] + r[2]);
        assertEquals("jmclbench: " + odo + ":2: a line longer than " + BoundedLineReader.MAX_LINE_CHARS + " characters\n",
                r[2]);
    }

    /**
     * A GC log of 64 MB ending in one line without an end (sparse, zeros after its first line):
     * read whole it took more than the 32 MB heap; now refused at that line.
     */
    @Test
    void aRunawayGcLogIsRefusedAtItsLineWithinASmallHeap(@TempDir Path tmp) throws Exception {
        Path key = runWithGcLog(tmp);
        Path log = key.resolve("gc.log");
        Files.writeString(log, "[0.003s][1044737680321ns][info][gc] Using Serial\n");
        try (RandomAccessFile f = new RandomAccessFile(log.toFile(), "rw")) {
            f.setLength(64L << 20);
        }
        Child c = explainInSmallHeap(tmp, key);
        assertEquals(2, c.exit(), c.err());
        assertEquals("jmclbench: " + log + ":2: a line longer than " + BoundedLineReader.MAX_LINE_CHARS + " characters", c.err().strip());
    }

    /**
     * A recording of 300 chunks (the fixture's, 43 MB), all before the run began (its clock a day
     * later): every event was loaded at once and took more than the 32 MB heap; now read one by one
     * and none kept, as none meets the run.
     */
    @Test
    void aRecordingFarLargerThanTheHeapIsReadEventByEvent(@TempDir Path tmp) throws Exception {
        Path key = ExplainCommandTest.runnerStyleRun(tmp, true);
        Path recording = key.resolve("recording.jfr");
        byte[] chunk = Files.readAllBytes(recording);
        try (OutputStream out = Files.newOutputStream(recording)) {
            for (int i = 0; i < 300; i++) {
                out.write(chunk);
            }
        }
        Path summary = key.resolve("local/nocov/400/QueueTest/1/summary.json");
        ObjectMapper json = new ObjectMapper();
        ObjectNode s = (ObjectNode) json.readTree(summary.toFile());
        ObjectNode clock = (ObjectNode) s.get("clock");
        long day = 86_400_000_000_000L;
        clock.put("runStartEpochNs", clock.get("runStartEpochNs").asLong() + day);
        clock.put("runStartNanoTime", clock.get("runStartNanoTime").asLong() + day);
        Files.writeString(summary, json.writeValueAsString(s));
        Child c = explainInSmallHeap(tmp, key);
        assertEquals(0, c.exit(), c.err());
        assertTrue(c.out().contains("events:  JFR " + recording + " ("), c.out());
        assertTrue(c.out().matches("(?s).*\ncauses:  [^\n]*\n.*") && !c.out().matches("(?s).*\ncauses:  [^\n]*\\bgc\\b.*"),
                "no pause meets the run: " + c.out());
    }

    /**
     * Keeping only the events that meet a missed job's window changes no attribution: each fixture's
     * recording and GC log explain every job as they do with every event kept (a safepoint that began
     * outside the windows and ended inside one was lost once, its two sides weighed one by one).
     */
    @Test
    void theEventsKeptExplainEveryJobAsAllEventsDo(@TempDir Path tmp) throws Exception {
        for (String jdk : Fixtures.JDKS) {
            Path fx = Fixtures.dir(jdk);
            RunClock clock = RunClock.fromText(fx.resolve("clock.txt"));
            List<JobRecord> jobs = JobFileReader.read(fx.resolve("jobs.txt"), "predict");
            for (String capture : List.of(JfrFlags.RECORDING, JfrFlags.GC_LOG)) {
                Path run = Files.createDirectories(tmp.resolve(jdk + "-" + capture));
                Files.copy(fx.resolve("jobs.txt"), run.resolve("odoData.txt"));
                Files.writeString(run.resolve("laserData.txt"), "# index release_ns start_ns end_ns deadline_ns outcome cpu_ns\n");
                Files.writeString(run.resolve("summary.json"), "{\"clock\": {\"runStartEpochNs\": " + clock.runStartEpochNs()
                        + ", \"runStartNanoTime\": " + clock.runStartNanoTime() + ", \"jvmStartEpochMs\": " + clock.jvmStartEpochMs() + "}}");
                Files.copy(fx.resolve(capture), run.resolve(capture));
                List<VmEvent> all = capture.equals(JfrFlags.RECORDING) ? JfrEventReader.read(fx.resolve(capture), clock)
                        : GcLogParser.parse(fx.resolve(capture), clock);
                RunEvidence kept = RunEvidence.load(run);
                assertTrue(kept.events().size() < all.size(), jdk + " " + capture + ": some event left out, or the test proves nothing");
                assertEquals(all.size(), kept.eventsRead(), jdk + " " + capture + ": every event counted as read");
                assertEquals(Attribution.attribute(jobs, all, Attribution.Settings.defaults()),
                        kept.attribute(Attribution.Settings.defaults()), jdk + " " + capture);
            }
        }
    }

    private record Child(int exit, String out, String err) {
    }

    /** {@code jmclbench explain KEY} in a child JVM of a 32 MB heap. */
    private static Child explainInSmallHeap(Path tmp, Path key) throws Exception {
        Path out = tmp.resolve("child.out");
        Path err = tmp.resolve("child.err");
        Process p = new ProcessBuilder(ProcessHandle.current().info().command().orElse("java"), "-Xmx32m",
                "-cp", System.getProperty("java.class.path"), "org.jmclbench.tooling.cli.JmclbenchCli",
                "explain", "--limit", "1", key.toString())
                .redirectOutput(out.toFile()).redirectError(err.toFile()).start();
        if (!p.waitFor(120, TimeUnit.SECONDS)) {
            p.destroyForcibly();
            throw new AssertionError("explain did not end");
        }
        return new Child(p.exitValue(), Files.readString(out, StandardCharsets.UTF_8), Files.readString(err, StandardCharsets.UTF_8));
    }
}
