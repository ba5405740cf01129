package org.jmclbench.tooling.attribution;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class JfrFlagsTest {

    @Test
    void jfrFromJdk11WithOurSettingsCopiedIntoTheRunDirectory(@TempDir Path tmp) throws Exception {
        EventCapture c = JfrFlags.forJava(11, tmp.resolve("runs/k"));
        assertEquals(EventCapture.Mode.JFR, c.mode());
        Path jfc = tmp.resolve("runs/k/jmclbench.jfc");
        assertEquals(List.of("-XX:StartFlightRecording=filename=" + tmp.resolve("runs/k/recording.jfr") + ",settings=" + jfc
                + ",dumponexit=true"), c.jvmArgs());
        assertTrue(Files.readString(jfc).contains("<event name=\"jdk.GCPhasePause\">"));
        assertTrue(JfrFlags.hasJfr(25));
    }

    @Test
    void gcLogsBeforeJdk11() {
        Path d = Path.of("/tmp/x");
        EventCapture nine = JfrFlags.forJava(9, d);
        assertEquals(EventCapture.Mode.UNIFIED_GC_LOG, nine.mode());
        assertEquals(List.of("-Xlog:gc,gc+phases,safepoint:file=/tmp/x/gc.log:uptime,timenanos,level,tags"), nine.jvmArgs());
        EventCapture eight = JfrFlags.forJava(8, d);
        assertEquals(EventCapture.Mode.LEGACY_GC_LOG, eight.mode());
        assertTrue(eight.jvmArgs().containsAll(List.of("-Xloggc:/tmp/x/gc.log", "-XX:+PrintGCDateStamps",
                "-XX:+PrintGCApplicationStoppedTime")));
        assertEquals(EventCapture.Mode.NONE, JfrFlags.forJava(7, d).mode());
    }

    @Test
    void theFlagsItAddsAreNamedWithoutTheirRunPathsAndOthersKeptWhole(@TempDir Path tmp) {
        Path run = tmp.resolve("runs/k");
        for (int version : new int[] { 8, 9, 11, 25 }) {
            for (String flag : JfrFlags.forJava(version, run).jvmArgs()) {
                String shown = JfrFlags.withoutRunPaths(flag);
                assertFalse(shown.contains(run.toString()), "JDK " + version + ": " + shown);
            }
        }
        assertEquals("-Xloggc (jmclbench's GC log, for the causes of misses)", JfrFlags.withoutRunPaths("-Xloggc:/r/gc.log"));
        assertEquals("-XX:+PrintGCDetails", JfrFlags.withoutRunPaths("-XX:+PrintGCDetails"));
        // a profile's own recording or log is part of the configuration: kept as written
        for (String own : List.of("-XX:StartFlightRecording=filename=/data/mine.jfr", "-Xloggc:/var/log/app-gc.log",
                "-Xlog:gc:file=/var/log/gc.log")) {
            assertEquals(own, JfrFlags.withoutRunPaths(own));
        }
    }

    @Test
    void aRunDirectoryTheJfrOptionCannotCarryIsRefused(@TempDir Path tmp) {
        assertThrows(IllegalArgumentException.class, () -> JfrFlags.forJava(17, tmp.resolve("a,b")));
    }
}
