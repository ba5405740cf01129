package org.jmclbench.tooling.attribution;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

class JfrEventReaderTest {

    @ParameterizedTest
    @ValueSource(strings = {"jdk11", "jdk17", "jdk21", "jdk25"})
    void readsPausesSafepointsAndCompilationsOfTheJobCode(String jdk) throws Exception {
        Path d = Fixtures.dir(jdk);
        List<VmEvent> events = JfrEventReader.read(d.resolve("recording.jfr"), RunClock.fromText(d.resolve("clock.txt")));
        List<VmEvent> pauses = events.stream().filter(e -> e.kind() == VmEventKind.GC_PAUSE).toList();
        assertTrue(pauses.size() >= 10, jdk + ": a 48 MB Serial heap under 150 MB/s collects often: " + pauses.size());
        assertTrue(pauses.stream().allMatch(p -> p.detail().matches("(DefNew|SerialOld).*#\\d+")), pauses.get(0).detail());
        assertTrue(events.stream().anyMatch(e -> e.kind() == VmEventKind.SAFEPOINT), jdk);
        assertTrue(events.stream().anyMatch(e -> e.kind() == VmEventKind.COMPILATION
                && e.detail().startsWith("org.jmclbench.workload.mcl.FixtureJobs.compute")), jdk + ": the job's code was compiled");
        // Sorted by start, and mostly inside the 3 s run (the recording starts before the run).
        for (int i = 1; i < events.size(); i++) {
            assertTrue(events.get(i - 1).startNs() <= events.get(i).startNs());
        }
        long inRun = pauses.stream().filter(p -> p.startNs() > -2_000_000_000L && p.endNs() < 5_000_000_000L).count();
        assertEquals(pauses.size(), inRun, jdk + ": every pause lies near the run");
    }

    /**
     * The same pause seen by JFR (wall clock) and by the GC log (nanoTime) starts at the same
     * place on the run's timeline: the two time bases are aligned. Not every one: the log line
     * of a full collection nested in a young one (Serial, JDK 11) is written when the outer
     * one ends, so its derived start lies late by the remaining work of the outer pause.
     */
    @ParameterizedTest
    @ValueSource(strings = {"jdk11", "jdk17", "jdk21", "jdk25"})
    void jfrAndGcLogAgreeOnWhenPausesStarted(String jdk) throws Exception {
        Path d = Fixtures.dir(jdk);
        RunClock clock = RunClock.fromText(d.resolve("clock.txt"));
        Map<String, VmEvent> logged = new HashMap<>();
        for (VmEvent e : GcLogParser.parse(d.resolve("gc.log"), clock)) {
            if (e.kind() == VmEventKind.GC_PAUSE) {
                logged.put(id(e), e);
            }
        }
        int compared = 0;
        int agreed = 0;
        for (VmEvent e : JfrEventReader.read(d.resolve("recording.jfr"), clock)) {
            VmEvent l = e.kind() == VmEventKind.GC_PAUSE ? logged.get(id(e)) : null;
            if (l != null) {
                compared++;
                long diff = Math.abs(l.startNs() - e.startNs());
                agreed += diff < 2_000_000L ? 1 : 0;
                assertTrue(diff < 100_000_000L, jdk + " GC " + id(e) + ": JFR starts at " + e.startNs() + ", the log at " + l.startNs());
            }
        }
        assertTrue(compared >= 10, jdk + ": compared " + compared);
        assertTrue(agreed >= 0.9 * compared, jdk + ": " + agreed + " of " + compared + " agree within 2 ms");
    }

    private static String id(VmEvent e) {
        return e.detail().substring(e.detail().lastIndexOf('#'));
    }
}
