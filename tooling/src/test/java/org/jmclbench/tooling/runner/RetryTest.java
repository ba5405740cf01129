package org.jmclbench.tooling.runner;

import static org.junit.jupiter.api.Assertions.assertEquals;
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

/** A failed run is final on resume; --retry-failed runs it again and replaces its row. */
class RetryTest {

    @TempDir
    Path dir;

    @Test
    void failedRunsAreRetriedOnlyWhenAsked() throws Exception {
        Fixtures.home(dir);
        Path fake = Fixtures.fakeJava(dir, "flaky", "crash", 0, null, 21);
        Path db = dir.resolve("out/results.db");
        String[] args = {"matrix", "--java", fake.toString(), "--datasets", "tiny", "--particles", "100", "--db", db.toString()};
        assertEquals(0, Fixtures.cli(args).exitCode());
        assertEquals("failed", status(db));

        Fixtures.CliResult resumed = Fixtures.cli(args);
        assertTrue(resumed.out().contains("1 already in") && resumed.out().contains("0 ran"), resumed.out());
        assertEquals("failed", status(db));

        // the runtime is repaired (same path, same version: same run key); only --retry-failed reruns it
        Files.writeString(fake, Files.readString(fake).replace("MODE=crash", "MODE=ok"));
        Files.setPosixFilePermissions(fake, PosixFilePermissions.fromString("rwxr-xr-x"));
        Fixtures.CliResult retried = Fixtures.cli(java.util.stream.Stream.concat(java.util.Arrays.stream(args),
                java.util.stream.Stream.of("--retry-failed")).toArray(String[]::new));
        assertTrue(retried.out().contains("1 ran (1 ok"), retried.out());
        assertEquals("ok", status(db));
        try (Connection c = DriverManager.getConnection("jdbc:sqlite:" + db); Statement s = c.createStatement();
             ResultSet rs = s.executeQuery("SELECT count(*) FROM runs")) {
            rs.next();
            assertEquals(1, rs.getInt(1));
        }
    }

    private static String status(Path db) throws Exception {
        try (Connection c = DriverManager.getConnection("jdbc:sqlite:" + db); Statement s = c.createStatement();
             ResultSet rs = s.executeQuery("SELECT status FROM runs")) {
            assertTrue(rs.next());
            return rs.getString(1);
        }
    }
}
