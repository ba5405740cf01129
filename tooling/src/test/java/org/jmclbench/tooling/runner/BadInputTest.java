package org.jmclbench.tooling.runner;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import org.jmclbench.tooling.Fixtures;
import org.junit.jupiter.api.Test;

/** Bad input is one line naming the option or file:line, exit code 2, and nothing run or recorded. */
class BadInputTest extends FakeJvmHome {

    private void assertRejected(String expected, String... args) {
        Fixtures.CliResult r = Fixtures.cli(args);
        assertEquals(2, r.exitCode(), r.out() + r.err());
        String err = r.err().strip();
        assertEquals(1, err.lines().count(), "one line: " + err);
        assertTrue(err.startsWith("jmclbench: "), err);
        assertTrue(err.contains(expected), err + " should contain " + expected);
        assertFalse(Files.exists(db), "nothing may be recorded");
        assertFalse(Files.exists(dir.resolve("out/runs")), "nothing may run");
    }

    @Test
    void unknownProfile() {
        assertRejected("--profiles: unknown profile component 'g2'", "matrix", "--java", fake.toString(),
                "--profiles", "g1,g2+fifo", "--datasets", "tiny", "--db", db.toString());
    }

    @Test
    void conflictingProfile() {
        assertRejected("two gc settings: g1 and zgc", "matrix", "--java", fake.toString(),
                "--profiles", "g1+zgc", "--datasets", "tiny", "--db", db.toString());
    }

    @Test
    void unknownRuntime() {
        assertRejected("--runtimes: unknown runtime 'nosuch-99'", "matrix", "--java", fake.toString(),
                "--runtimes", "nosuch-99", "--datasets", "tiny", "--db", db.toString());
    }

    @Test
    void pathThatIsNotAJvm() throws Exception {
        Path notJvm = dir.resolve("not-java");
        Files.writeString(notJvm, "#!/bin/sh\necho hello\n");
        notJvm.toFile().setExecutable(true);
        assertRejected("--java: " + notJvm + ": not a JVM", "matrix", "--java", notJvm.toString(),
                "--datasets", "tiny", "--db", db.toString());
        assertRejected("--java: /no/such/java: not a JVM (no such file)", "matrix", "--java", "/no/such/java",
                "--datasets", "tiny", "--db", db.toString());
    }

    @Test
    void badMatrixFileNamesFileAndLine() throws Exception {
        Path m = dir.resolve("m.properties");
        Files.writeString(m, "# a matrix\nprofiles = g1\nparticles = 100, many\n");
        assertRejected(m + ":3: particles: 'many' is not a positive integer", "matrix", "--matrix", m.toString(),
                "--java", fake.toString(), "--datasets", "tiny", "--db", db.toString());
        Files.writeString(m, "profiles = g1\npolicies = skip,\n");
        assertRejected(m + ":2: policies: empty item in 'skip,'", "matrix", "--matrix", m.toString(),
                "--java", fake.toString(), "--datasets", "tiny", "--db", db.toString());
        Files.writeString(m, "repeat = 2\nparticles = 100\nparticles = 200\nrepeat = 3\n");
        assertRejected(m + ":4: repeat: set twice (also at line 1)", "matrix", "--matrix", m.toString(),
                "--java", fake.toString(), "--datasets", "tiny", "--db", db.toString());
        Files.writeString(m, "profiles = g1\n\ncolour = blue\n");
        assertRejected(m + ":3: unknown key 'colour'", "matrix", "--matrix", m.toString(), "--java", fake.toString(),
                "--datasets", "tiny", "--db", db.toString());
        Files.writeString(m, "java = " + fake + "\nprofiles = g1\nruntimes = fake-21, nosuch-1\ndatasets = tiny\n");
        assertRejected(m + ":3: runtimes: unknown runtime 'nosuch-1'", "matrix", "--matrix", m.toString(),
                "--db", db.toString());
        Files.writeString(m, "java = " + fake + "\nprofiles = g1\nthis line has no equals sign\n");
        assertRejected(m + ":3: expected 'key = value'", "matrix", "--matrix", m.toString(), "--db", db.toString());
        assertRejected("--matrix: " + dir.resolve("missing") + ": cannot read", "matrix", "--matrix",
                dir.resolve("missing").toString(), "--db", db.toString());
    }

    @Test
    void badOptionValues() {
        assertRejected("--particles: '0' is not a positive integer", "matrix", "--java", fake.toString(),
                "--particles", "100,0", "--datasets", "tiny", "--db", db.toString());
        // a trailing empty item is as empty as one between commas (',' alone ran the default 400)
        assertRejected("--particles: empty item in '100,'", "matrix", "--java", fake.toString(),
                "--particles", "100,", "--datasets", "tiny", "--db", db.toString());
        assertRejected("--particles: empty item in ','", "matrix", "--java", fake.toString(),
                "--particles", ",", "--datasets", "tiny", "--db", db.toString());
        assertRejected("--load-alloc: '100,16,' must be MBPS,LIVEMB", "matrix", "--java", fake.toString(),
                "--load-alloc", "100,16,", "--datasets", "tiny", "--db", db.toString());
        // planning a repetition count this large never ended (the last one overflowed the loop)
        assertRejected("--repeat: '2147483647' is more than 10000 repetitions", "matrix", "--java", fake.toString(),
                "--repeat", "2147483647", "--datasets", "tiny", "--db", db.toString());
        assertRejected("--policies: unknown policy 'drop'", "matrix", "--java", fake.toString(),
                "--policies", "skip,drop", "--datasets", "tiny", "--db", db.toString());
        assertRejected("--shard: '3/2' is not a shard", "matrix", "--java", fake.toString(),
                "--shard", "3/2", "--datasets", "tiny", "--db", db.toString());
        assertRejected("--datasets: dataset 'nosuch': no such folder", "matrix", "--java", fake.toString(),
                "--datasets", "nosuch", "--db", db.toString());
        assertRejected("--workload-arg: empty value", "matrix", "--java", fake.toString(),
                "--datasets", "tiny", "--workload-arg", " ", "--db", db.toString());
        assertRejected("--workload-arg: '--seed' is set by the runner", "matrix", "--java", fake.toString(),
                "--datasets", "tiny", "--workload-arg", "--seed 3", "--db", db.toString());
        // the workload's range, refused before the matrix rather than by each of its runs
        assertRejected("--time-scale: '1e-9' is out of range [1e-6, 1000]", "matrix", "--java", fake.toString(),
                "--time-scale", "1e-9", "--datasets", "tiny", "--db", db.toString());
    }

    @Test
    void databaseThatIsNotOne() throws Exception {
        Files.createDirectories(db.getParent());
        Files.writeString(db, "not a database, just text that happens to sit here");
        Fixtures.CliResult r = Fixtures.cli("matrix", "--java", fake.toString(), "--datasets", "tiny", "--db", db.toString());
        assertEquals(2, r.exitCode(), r.out() + r.err());
        assertTrue(r.err().strip().startsWith("jmclbench: --db: " + db + ": not a usable results store"), r.err());
        assertEquals("not a database, just text that happens to sit here", Files.readString(db));
        assertFalse(Files.exists(dir.resolve("out/runs")));
    }

    /**
     * A dry run shows what the run would do: a store the run would refuse (its folder below a file, a
     * file that is no SQLite database, a database without the runs table) is refused by the dry run too,
     * with the run's own line, and nothing is created or changed.
     */
    @Test
    void aDryRunRefusesTheDatabaseTheRunWouldRefuse() throws Exception {
        Path file = Files.writeString(dir.resolve("a-file"), "text");
        Path below = file.resolve("results.db");
        Path text = Files.writeString(dir.resolve("text.db"), "not a database, just text that happens to sit here");
        Path other = dir.resolve("other.db");
        try (java.sql.Connection c = java.sql.DriverManager.getConnection("jdbc:sqlite:" + other);
             java.sql.Statement s = c.createStatement()) {
            s.execute("CREATE TABLE notes (text TEXT)");
        }
        byte[] otherBytes = Files.readAllBytes(other);
        Path m = Files.writeString(dir.resolve("e.txt"), "datasets = tiny\n[a]\nruntimes = native\n");
        String[][] refused = {
            {below.toString(), "--db: " + below + ": cannot write there (" + file + " is a file)"},
            {text.toString(), "--db: " + text + ": not a usable results store ("},
            {other.toString(), "--db: " + other + ": not a usable results store (no runs table)"},
        };
        for (String[] r : refused) {
            Fixtures.CliResult run = Fixtures.cli("matrix", "--java", fake.toString(), "--datasets", "tiny", "--db", r[0]);
            assertEquals(2, run.exitCode(), run.out() + run.err());
            assertTrue(run.err().strip().startsWith("jmclbench: " + r[1]), run.err());
            for (String[] dryRun : List.of(
                    new String[] {"matrix", "--dry-run", "--java", fake.toString(), "--datasets", "tiny", "--db", r[0]},
                    new String[] {"evaluate", "--dry-run", "--matrix", m.toString(), "--db", r[0]})) {
                Fixtures.CliResult dry = Fixtures.cli(dryRun);
                assertEquals(2, dry.exitCode(), dryRun[0] + ": " + dry.out() + dry.err());
                assertEquals(run.err().strip(), dry.err().strip(), dryRun[0] + " --dry-run refuses as the run does");
                assertFalse(dry.out().contains("planned") || dry.out().contains("budget"), "no plan for a refused store: " + dry.out());
            }
        }
        assertEquals("text", Files.readString(file));
        assertEquals("not a database, just text that happens to sit here", Files.readString(text));
        assertArrayEquals(otherBytes, Files.readAllBytes(other), "a dry run changes nothing");
        assertFalse(Files.exists(dir.resolve("out/runs")), "nothing may run");
    }

    @Test
    void matrixFileAndCommandLineCombine() throws Exception {
        Path m = dir.resolve("m.properties");
        Files.writeString(m, "java = " + fake + "\nprofiles = g1, zgc\nparticles = 100\nparticles = 200\n"
                + "policies = skip\ndatasets = tiny\nrepeat = 2\n");
        Fixtures.CliResult r = Fixtures.cli("matrix", "--matrix", m.toString(), "--particles", "300", "--dry-run",
                "--db", db.toString());
        assertEquals(0, r.exitCode(), r.err());
        // 2 profiles x 1 size (the command line replaced the file's two) x 2 repetitions
        assertTrue(r.out().startsWith("4 runs planned"), r.out());
        assertTrue(r.out().contains("fake-21 zgc skip 300p tiny #2"), r.out());
        assertFalse(Files.exists(db));
    }
}
