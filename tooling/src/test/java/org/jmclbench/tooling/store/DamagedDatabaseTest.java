package org.jmclbench.tooling.store;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;
import java.util.function.UnaryOperator;

import org.jmclbench.tooling.Fixtures;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * A results database that was truncated (a copy cut short, a full disk) or corrupted (a page overwritten)
 * is refused by every command that opens one, to read (report, compare, evaluate's document), to write
 * or to merge: one line naming the file, exit code 2, and the file's bytes as they were (no repair, no
 * migration, no new rows).
 */
class DamagedDatabaseTest {

    /** SQLite's page size for the stores this tool creates. */
    private static final int PAGE = 4096;

    @TempDir
    Path dir;

    private Path good;
    private String fake;

    @BeforeEach
    void store() throws Exception {
        Fixtures.home(dir);
        fake = Fixtures.fakeJava(dir, "a", "ok", 0, null, 21).toString();
        good = dir.resolve("good/results.db");
        Fixtures.CliResult r = Fixtures.cli("matrix", "--java", fake, "--datasets", "tiny", "--particles", "100,200,300",
                "--policies", "skip,terminate", "--db", good.toString());
        assertEquals(0, r.exitCode(), r.out() + r.err());
        assertTrue(Files.size(good) > 8 * PAGE, "the store spans pages enough to damage one in the middle: " + Files.size(good));
    }

    /** The damages tried, each on a copy of the good store. */
    private List<Damage> damages() {
        return List.of(
                new Damage("half", b -> Arrays.copyOf(b, b.length / 2 / PAGE * PAGE)),
                new Damage("cut-mid-page", b -> Arrays.copyOf(b, b.length - PAGE / 2)),
                new Damage("header-zeroed", b -> {
                    Arrays.fill(b, 0, 100, (byte) 0);
                    return b;
                }),
                new Damage("page-overwritten", b -> {
                    int page = b.length / PAGE / 2;
                    Arrays.fill(b, page * PAGE, (page + 1) * PAGE, (byte) 0xA5);
                    return b;
                }));
    }

    private record Damage(String name, UnaryOperator<byte[]> how) {
    }

    private Path damaged(Damage d) throws IOException {
        Path p = dir.resolve(d.name()).resolve("results.db");
        Files.createDirectories(p.getParent());
        Files.write(p, d.how().apply(Files.readAllBytes(good)));
        return p;
    }

    /** Runs the command line, expecting a refusal that names {@code db} and leaves it byte for byte. */
    private void assertRefused(Path db, String... args) throws IOException {
        byte[] before = Files.readAllBytes(db);
        Fixtures.CliResult r = Fixtures.cli(args);
        String what = String.join(" ", args);
        assertEquals(2, r.exitCode(), what + "\n" + r.out() + r.err());
        assertEquals(1, r.err().strip().lines().count(), what + ": one line\n" + r.err());
        assertTrue(r.err().startsWith("jmclbench: ") && r.err().contains(db.toString()), what + ": names the file\n" + r.err());
        assertArrayEquals(before, Files.readAllBytes(db), what + ": the file was changed");
        assertFalse(Files.exists(db.resolveSibling(db.getFileName() + "-journal")), what + ": a journal was left");
    }

    @Test
    void everyCommandRefusesADamagedStoreAndLeavesIt() throws Exception {
        for (Damage d : damages()) {
            Path db = damaged(d);
            Path folder = db.getParent();
            assertRefused(db, "report", "--db", db.toString(), "--out", folder.resolve("report").toString());
            assertFalse(Files.exists(folder.resolve("report")), d.name() + ": no report from a damaged store");
            assertRefused(db, "compare", good.toString(), db.toString());
            assertRefused(db, "matrix", "--java", fake, "--datasets", "tiny", "--particles", "400", "--db", db.toString());
            assertFalse(Files.exists(folder.resolve("runs")), d.name() + ": no run started on a damaged store");
            Path into = folder.resolve("merged.db");
            assertRefused(db, "merge", good.toString(), db.toString(), "--into", into.toString());
            assertFalse(Files.exists(into), d.name() + ": the target is not created when a source is refused");
            assertRefused(db, "merge", good.toString(), "--into", db.toString());
            Path evaluation = Files.writeString(folder.resolve("evaluation.txt"), "datasets = tiny\n[a]\nruntimes = native\n");
            assertRefused(db, "evaluate", "--no-run", "--matrix", evaluation.toString(), "--db", db.toString(),
                    "--out", folder.resolve("doc/evaluation").toString());
            assertFalse(Files.exists(folder.resolve("doc")), d.name() + ": no document from a damaged store");
        }
    }

    @Test
    void aFileWithARunsTableButNotAStoresTablesIsRefused() throws Exception {
        // a runs table and a known version, but not the tables and columns a merge copies
        Path db = dir.resolve("other/results.db");
        Files.createDirectories(db.getParent());
        try (java.sql.Connection c = java.sql.DriverManager.getConnection("jdbc:sqlite:" + db);
                java.sql.Statement s = c.createStatement()) {
            s.execute("CREATE TABLE runs (x)");
            s.execute("INSERT INTO runs VALUES (1)");
            s.execute("PRAGMA user_version = 3");
        }
        Path into = dir.resolve("merged/results.db");
        assertRefused(db, "merge", db.toString(), "--into", into.toString());
        assertFalse(Files.exists(into), "no empty store left as if merged");
        assertRefused(db, "report", "--db", db.toString(), "--out", dir.resolve("other/report").toString());
    }

    @Test
    void theUndamagedStoreStillReads() {
        // the control: the same commands on the good store succeed, so the refusals above are the damage's
        Fixtures.CliResult r = Fixtures.cli("report", "--db", good.toString(), "--out", dir.resolve("r").toString(), "--no-export");
        assertEquals(0, r.exitCode(), r.err());
        r = Fixtures.cli("merge", good.toString(), "--into", dir.resolve("m/results.db").toString());
        assertEquals(0, r.exitCode(), r.err());
        assertTrue(r.out().contains("6 runs merged"), r.out());
    }
}
