package org.jmclbench.tooling.attribution;

import static org.junit.jupiter.api.Assertions.assertEquals;
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
    void aRunDirectoryTheJfrOptionCannotCarryIsRefused(@TempDir Path tmp) {
        assertThrows(IllegalArgumentException.class, () -> JfrFlags.forJava(17, tmp.resolve("a,b")));
    }
}
