package org.jmclbench.tooling.runner;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.sql.Connection;
import java.sql.DriverManager;
import java.sql.ResultSet;
import java.sql.Statement;

import org.jmclbench.tooling.Fixtures;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * An SCJ memory area that overflows, through the matrix on a real JVM (the scj engine of the test's
 * class path): the run is recorded failed with the area named, no summary kept, and the matrix goes on.
 * The HVM's overflow is named the same way (HvmFailureTest, HvmRunTest in hvm/launcher).
 */
class AreaOverflowMatrixTest {

    @TempDir
    Path dir;

    @Test
    void anOverflowingAreaIsThatRunsRecordedFailureNamed() throws Exception {
        Fixtures.home(dir);
        Path repo = Path.of(System.getProperty("user.dir")).toAbsolutePath().getParent();
        // this JVM, running the workload from the test's class path in place of the stand-in jar
        Path java = dir.resolve("jvm/bin/java");
        Files.createDirectories(java.getParent());
        Files.writeString(java, String.join("\n", "#!/usr/bin/env bash",
                "args=()",
                "for a in \"$@\"; do",
                "    case $a in *jmclbench-workload.jar) a='" + System.getProperty("java.class.path") + "' ;; esac",
                "    args+=(\"$a\")",
                "done",
                "exec '" + ProcessHandle.current().info().command().orElse("java") + "' \"${args[@]}\"", ""));
        Files.setPosixFilePermissions(java, PosixFilePermissions.fromString("rwxr-xr-x"));
        Path db = dir.resolve("out/results.db");
        Fixtures.CliResult r = Fixtures.cli("matrix", "--java", java.toString(), "--engines", "scj",
                "--particles", "100,4000", "--datasets", repo.resolve("data/match-quick").toString(), "--time-scale", "0.1",
                "--workload-arg", "--area-size mission=70000", "--order-seed", "1", "--db", db.toString());
        assertEquals(0, r.exitCode(), r.out() + r.err());
        assertTrue(r.out().contains("1 ok, 1 failed"), "100 particles fit 70000 bytes of mission memory, 4000 do not: " + r.out());
        try (Connection c = DriverManager.getConnection("jdbc:sqlite:" + db); Statement s = c.createStatement();
             ResultSet rs = s.executeQuery("SELECT status, failure, summary_json FROM runs WHERE particles = 4000")) {
            assertTrue(rs.next());
            assertEquals("failed", rs.getString(1));
            assertTrue(rs.getString(2).contains("memory area 'mission' overflowed"), rs.getString(2));
            assertNull(rs.getString(3), "nothing of the run recorded as valid");
            assertFalse(rs.next());
        }
    }
}
