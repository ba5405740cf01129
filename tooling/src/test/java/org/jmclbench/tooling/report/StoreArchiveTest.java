package org.jmclbench.tooling.report;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.sql.Connection;
import java.sql.DriverManager;
import java.sql.ResultSet;
import java.sql.Statement;
import java.util.Map;
import java.util.TreeMap;

import org.jmclbench.tooling.store.StoreArchive;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The evaluation's committed data: an archive keeps every run and every series the document
 * reads, leaves out the per-run trajectory and deviation series, and restores to a store that
 * opens like the original.
 */
class StoreArchiveTest {
    @TempDir
    Path dir;

    private static Map<String, Integer> counts(Path db) throws Exception {
        Map<String, Integer> n = new TreeMap<>();
        try (Connection c = DriverManager.getConnection("jdbc:sqlite:" + db); Statement s = c.createStatement()) {
            try (ResultSet r = s.executeQuery("SELECT name, count(*) FROM series GROUP BY name")) {
                while (r.next()) {
                    n.put("series " + r.getString(1), r.getInt(2));
                }
            }
            for (String table : new String[] {"runs", "metrics", "histograms"}) {
                try (ResultSet r = s.executeQuery("SELECT count(*) FROM " + table)) {
                    n.put(table, r.getInt(1));
                }
            }
        }
        return n;
    }

    @Test
    void anArchiveLeavesOutTheSeriesNoDocumentReadsAndKeepsTheRest() throws Exception {
        Path db = ReportFixtures.write(ReportFixtures.mixed(), dir, "results.db");
        Map<String, Integer> before = counts(db);
        assertTrue(before.get("series trajectory") > 0 && before.get("series deviation") > 0, "the fixture has both: " + before);
        Path archive = dir.resolve("data/evaluation.db.gz");
        StoreArchive.write(db, archive);
        Path restored = StoreArchive.extract(archive, Files.createDirectories(dir.resolve("out")), "--data");
        Map<String, Integer> expected = new TreeMap<>(before);
        StoreArchive.LEFT_OUT.forEach(name -> expected.remove("series " + name));
        assertEquals(expected, counts(restored));
        assertTrue(Files.size(archive) < Files.size(db), "compressed: " + Files.size(archive) + " vs " + Files.size(db));
    }
}
