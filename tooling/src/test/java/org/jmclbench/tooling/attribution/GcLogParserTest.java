package org.jmclbench.tooling.attribution;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.time.OffsetDateTime;
import java.util.List;
import java.util.regex.Pattern;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

class GcLogParserTest {
    private static final Pattern PAUSE_LINE = Pattern.compile("\\[gc(,phases)?\\s*\\].*GC\\(\\d+\\).*Pause.*\\d+ms$");

    @ParameterizedTest
    @ValueSource(strings = {"jdk11", "jdk17", "jdk21", "jdk25", "jdk11/uptime", "jdk17/uptime", "jdk21/uptime",
            "jdk25/uptime", "jdk17/zgc", "jdk21/zgc", "jdk25/zgc"})
    void findsEveryPauseOfARecordedLogAndPlacesItNearTheRun(String fixture) throws Exception {
        Path d = Fixtures.dir(fixture);
        Path log = d.resolve("gc.log");
        long expected = Files.readAllLines(log).stream().filter(l -> PAUSE_LINE.matcher(l).find()).count();
        List<VmEvent> events = GcLogParser.parse(log, RunClock.fromText(d.resolve("clock.txt")));
        List<VmEvent> pauses = events.stream().filter(e -> e.kind() == VmEventKind.GC_PAUSE).toList();
        assertTrue(expected > 0, fixture);
        assertEquals(expected, pauses.size(), fixture);
        for (VmEvent p : pauses) {
            // The program runs about 1 s before the run start (JVM start, JFR) and 3 s after it.
            assertTrue(p.startNs() > -3_000_000_000L && p.endNs() < 4_000_000_000L, fixture + ": " + p);
            assertTrue(p.durationNs() >= 0 && p.durationNs() < 1_000_000_000L, fixture + ": " + p);
        }
        if (!fixture.contains("uptime")) {
            assertTrue(events.stream().anyMatch(e -> e.kind() == VmEventKind.SAFEPOINT), fixture + ": safepoint lines");
        }
        if (fixture.contains("zgc")) {
            assertTrue(pauses.stream().allMatch(p -> p.detail().contains("Z Garbage Collector")), pauses.get(0).detail());
        }
    }

    @Test
    void unifiedLinesOfEachJdkGeneration() {
        RunClock clock = new RunClock(1_000_000_000_000L, 5_000_000_000L, -1);
        List<VmEvent> e = GcLogParser.parse(List.of(
                "[0.004s][5000000000ns][info][gc] Using G1",
                "[0.100s][5010000000ns][info][gc          ] GC(3) Pause Young (Normal) (G1 Evacuation Pause) 24M->3M(256M) 3.500ms",
                "[0.200s][5020000000ns][info][gc,phases] GC(4) Y: Pause Mark Start (Major) 0.018ms",
                "[0.300s][5030000000ns][info][safepoint   ] Safepoint \"G1CollectForAllocation\", Time since last: 1 ns, Reaching safepoint: 5892 ns, Cleanup: 1 ns, At safepoint: 17849 ns, Total: 2000000 ns",
                "[0.400s][5040000000ns][info][safepoint    ] Entering safepoint region: ICBufferFull",
                "[0.401s][5041000000ns][info][safepoint    ] Leaving safepoint region",
                "[0.402s][5042000000ns][info][safepoint    ] Total time for which application threads were stopped: 0.0010000 seconds, Stopping threads took: 0.0000739 seconds",
                "[0.500s][5050000000ns][info][gc,heap] GC(5) Eden regions: 3->0(3)"), clock);
        assertEquals(List.of(
                new VmEvent(VmEventKind.GC_PAUSE, 6_500_000, 10_000_000, null, "G1 Pause Young (Normal) (G1 Evacuation Pause) #3"),
                new VmEvent(VmEventKind.GC_PAUSE, 19_982_000, 20_000_000, null, "G1 Y: Pause Mark Start (Major) #4"),
                new VmEvent(VmEventKind.SAFEPOINT, 28_000_000, 30_000_000, null, "G1CollectForAllocation"),
                new VmEvent(VmEventKind.SAFEPOINT, 41_000_000, 42_000_000, null, "ICBufferFull")), e);
    }

    @Test
    void uptimeOnlyLinesArePlacedByTheJvmStartTime() {
        // JVM started 2 s before the run: uptime 2.010 s is 10 ms into the run.
        RunClock clock = new RunClock(1_000_002_000_000_000L, 0, 1_000_000_000L);
        List<VmEvent> e = GcLogParser.parse(List.of("[2.010s][info][gc] GC(0) Pause Full (System.gc()) 5M->1M(48M) 4.000ms"), clock);
        assertEquals(List.of(new VmEvent(VmEventKind.GC_PAUSE, 6_000_000, 10_000_000, null, "GC Pause Full (System.gc()) #0")), e);
        // Without the JVM start time such a line cannot be placed and is left out.
        assertEquals(List.of(), GcLogParser.parse(List.of("[2.010s][info][gc] GC(0) Pause Full (System.gc()) 5M->1M(48M) 4.000ms"),
                new RunClock(0, 0, -1)));
    }

    @Test
    void jdk8DateStampedLog() throws Exception {
        long runStart = epochNs("2026-11-22T02:30:00.150+0000");
        RunClock clock = new RunClock(runStart, 0, -1);
        List<VmEvent> e = GcLogParser.parse(Fixtures.dir("jdk8-handwritten").resolve("gc.log"), clock);
        assertEquals(List.of(
                new VmEvent(VmEventKind.GC_PAUSE, 11_000_000, 19_254_000, null, "GC (Allocation Failure)"),
                new VmEvent(VmEventKind.SAFEPOINT, 11_688_000, 20_000_000, null, "safepoint"),
                new VmEvent(VmEventKind.SAFEPOINT, 249_999_000, 296_000_000, null, "safepoint"),
                new VmEvent(VmEventKind.GC_PAUSE, 250_000_000, 295_906_700, null, "GC (Allocation Failure)"),
                new VmEvent(VmEventKind.GC_PAUSE, 850_000_000, 880_100_000, null, "Full GC (System.gc())"),
                new VmEvent(VmEventKind.GC_PAUSE, 1_350_000_000, 1_351_200_000, null, "GC (CMS Initial Mark)"),
                new VmEvent(VmEventKind.GC_PAUSE, 1_850_000_000, 1_853_123_400, null, "GC pause (G1 Evacuation Pause) (young)")),
                e);
    }

    @Test
    void jdk8UptimeLog() throws Exception {
        // JVM start 100 ms before the run start.
        RunClock clock = new RunClock(1_000_000_100_000_000L, 0, 1_000_000_000L);
        List<VmEvent> e = GcLogParser.parse(Fixtures.dir("jdk8-handwritten").resolve("gc-uptime.log"), clock);
        assertEquals(3, e.size());
        assertEquals(new VmEvent(VmEventKind.GC_PAUSE, 61_000_000, 69_254_000, null, "GC (Allocation Failure)"), e.get(0));
        assertEquals(new VmEvent(VmEventKind.GC_PAUSE, 300_000_000, 345_906_700, null, "Full GC (Ergonomics)"), e.get(2));
    }

    private static long epochNs(String jdk8Stamp) {
        OffsetDateTime t = OffsetDateTime.parse(jdk8Stamp.replace("+0000", "+00:00"));
        return t.toEpochSecond() * 1_000_000_000L + t.getNano();
    }

    @ParameterizedTest
    @ValueSource(strings = {"jdk11/gc.log", "jdk17/gc.log", "jdk21/gc.log", "jdk25/gc.log", "jdk17/uptime/gc.log",
            "jdk25/zgc/gc.log", "jdk8-handwritten/gc.log", "jdk8-handwritten/gc-uptime.log"})
    void aRecordedLogIsAGcLog(String fixture) throws Exception {
        assertTrue(GcLogParser.isGcLog(Fixtures.dir(fixture)), fixture);
    }

    /** Where explain --events draws the line: a log's format lines without a pause are a GC log, other text is not. */
    @Test
    void aLogWithoutPausesIsAGcLogButOtherTextIsNot(@TempDir Path tmp) throws Exception {
        // -Xlog:gc of a JVM that never collected: its start line only
        assertTrue(isGcLog(tmp, "[0.003s][1044737680321ns][info][gc] Using Serial\n"));
        // a JDK 8 -Xloggc file before its first entry: the header
        assertTrue(isGcLog(tmp, "OpenJDK 64-Bit Server VM (25.392-b08) for linux-amd64 JRE (1.8.0_392-b08)\n"
                + "Memory: 4k page, physical 8000000k(1000000k free), swap 0k(0k free)\n"
                + "CommandLine flags: -XX:+PrintGC -XX:+PrintGCDateStamps\n"));
        assertTrue(isGcLog(tmp, ""), "--gc-log's file when nothing stopped the world");
        assertTrue(GcLogParser.parse(List.of("[0.003s][1044737680321ns][info][gc] Using Serial"),
                RunClock.fromText(Fixtures.dir("jdk17").resolve("clock.txt"))).isEmpty(), "a log of no events");
        assertTrue(!isGcLog(tmp, "run 3 was slow\n\nsee the recording\n"));
        assertTrue(!isGcLog(tmp, "[section]\nkey=value\n"), "bracketed, but tagged neither gc nor safepoint");
        assertTrue(!isGcLog(tmp, "3.14: [pi]\n[2026-13-45Tx] odd\n"), "stamped, but no GC entry");
        Files.write(tmp.resolve("bin"), new byte[] {'F', 'L', 'R', 0, (byte) 0xff, (byte) 0xfe, '\n', 1, 2});
        assertTrue(!GcLogParser.isGcLog(tmp.resolve("bin")), "a recording not named .jfr");
    }

    private static boolean isGcLog(Path tmp, String text) throws Exception {
        Path f = Files.writeString(Files.createTempFile(tmp, "log", ".txt"), text);
        return GcLogParser.isGcLog(f);
    }
}
