package org.jmclbench.tooling.store;

import java.io.IOException;
import java.nio.file.FileVisitResult;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.SimpleFileVisitor;
import java.nio.file.StandardCopyOption;
import java.nio.file.attribute.BasicFileAttributes;
import java.sql.PreparedStatement;
import java.sql.ResultSet;
import java.sql.SQLException;
import java.sql.Statement;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.stream.Stream;

/**
 * Merges results stores (two machines, two shards) into one: every run is kept once by its run key;
 * when both have it, an ok run wins over a failed one, otherwise the one already in the target stays.
 * Run folders are copied with their rows. A source of an older schema version (1) is read as it is:
 * its runs get the engine and memory style the migration gives them ({@link Schema#FILL_ENGINES}).
 */
public final class StoreMerger {

    /**
     * How many runs a merge took from one source, how many it left because the target had them, and
     * how many of those it left out although they are other measurements: ok runs whose key (the
     * same configuration and repetition on the same machine id) the target holds from another start.
     */
    public record Outcome(int taken, int kept, int measuredAgain) {
    }

    private StoreMerger() {
    }

    /**
     * Merges {@code source} into {@code target}.
     *
     * @throws org.jmclbench.tooling.cli.BadUsageException when the source is not a store this tool reads
     *                                                     ({@link ResultsDatabase#openToRead}); nothing is merged then
     */
    public static Outcome merge(RunRecorder target, Path source) throws SQLException, IOException {
        Path src = source.toAbsolutePath().normalize();
        // the same file by another name (a link) too: attaching it would wait on the target's own write lock
        if (src.equals(target.dbFile()) || Files.isSameFile(src, target.dbFile())) {
            // every run of the source is already in the target: say so, not "0 already in"
            try (Statement s = target.connection().createStatement(); ResultSet rs = s.executeQuery("SELECT count(*) FROM runs")) {
                return new Outcome(0, rs.next() ? rs.getInt(1) : 0, 0);
            }
        }
        ResultsDatabase.openToRead(source, null).close();
        var conn = target.connection();
        try (Statement s = conn.createStatement()) {
            conn.commit();
            conn.setAutoCommit(true); // ATTACH cannot run inside a transaction
            try (PreparedStatement ps = conn.prepareStatement("ATTACH DATABASE ? AS src")) {
                ps.setString(1, src.toString());
                ps.execute();
            }
            conn.setAutoCommit(false);
            List<String> staged = new ArrayList<>();
            List<String> take = new ArrayList<>();
            boolean committed = false;
            try {
                java.util.Map<String, String> columns = new java.util.HashMap<>();
                for (String t : Schema.RUN_TABLES) {
                    List<String> common = columns(s, "src", t);
                    common.retainAll(columns(s, "main", t));
                    if (!common.isEmpty()) {
                        columns.put(t, String.join(", ", common));
                    }
                }
                s.executeUpdate("INSERT OR IGNORE INTO machines SELECT * FROM src.machines");
                s.executeUpdate("INSERT OR IGNORE INTO matrices SELECT * FROM src.matrices");
                int total = 0;
                try (ResultSet rs = s.executeQuery("SELECT r.run_key FROM src.runs r LEFT JOIN main.runs m ON m.run_key = r.run_key"
                        + " WHERE m.run_key IS NULL OR (m.status <> 'ok' AND r.status = 'ok')")) {
                    while (rs.next()) {
                        take.add(rs.getString(1));
                    }
                }
                try (ResultSet rs = s.executeQuery("SELECT count(*) FROM src.runs")) {
                    total = rs.next() ? rs.getInt(1) : 0;
                }
                int measuredAgain;
                try (ResultSet rs = s.executeQuery("SELECT count(*) FROM src.runs r JOIN main.runs m ON m.run_key = r.run_key"
                        + " WHERE r.status = 'ok' AND m.status = 'ok'"
                        + " AND (r.started_at IS NOT m.started_at OR r.summary_json IS NOT m.summary_json)")) {
                    measuredAgain = rs.next() ? rs.getInt(1) : 0;
                }
                Path srcBase = src.getParent();
                for (String key : take) {
                    for (String t : Schema.RUN_TABLES) {
                        try (PreparedStatement del = conn.prepareStatement("DELETE FROM main." + t + " WHERE run_key = ?")) {
                            del.setString(1, key);
                            del.executeUpdate();
                        }
                        String cols = columns.get(t);
                        if (cols == null) {
                            continue; // a table the source's version did not have
                        }
                        try (PreparedStatement ins = conn.prepareStatement("INSERT INTO main." + t + " (" + cols + ") SELECT "
                                + cols + " FROM src." + t + " WHERE run_key = ?")) {
                            ins.setString(1, key);
                            ins.executeUpdate();
                        }
                    }
                    // copied beside the target's folder and swapped in only once the rows are committed, so that a
                    // merge that fails leaves the target's folders as they were
                    Path stage = staging(target.runFolder(key));
                    Path from = srcBase.resolve(RunRecorder.RUNS).resolve(key);
                    String runDir = null;
                    try (PreparedStatement q = conn.prepareStatement("SELECT run_dir FROM src.runs WHERE run_key = ?")) {
                        q.setString(1, key);
                        try (ResultSet rs = q.executeQuery()) {
                            runDir = rs.next() ? rs.getString(1) : null;
                        }
                    }
                    if (runDir != null) {
                        // the source's own runs folder (runs/ or runs-<name>/), and the same place in the target's
                        Path rel = Path.of(runDir);
                        int at = indexOf(rel, key);
                        if (at >= 0) {
                            from = srcBase.resolve(rel.subpath(0, at + 1));
                            Path inTarget = at + 1 < rel.getNameCount()
                                    ? target.runFolder(key).resolve(rel.subpath(at + 1, rel.getNameCount())) : target.runFolder(key);
                            try (PreparedStatement u = conn.prepareStatement("UPDATE main.runs SET run_dir = ? WHERE run_key = ?")) {
                                u.setString(1, target.baseDir().relativize(inTarget).toString());
                                u.setString(2, key);
                                u.executeUpdate();
                            }
                        }
                    }
                    try {
                        copyTree(from, stage);
                    } catch (IOException e) {
                        // a file system exception's message is often only a path: say what failed, and why
                        throw new IOException("cannot copy the run folder " + from + ": " + e.getClass().getSimpleName() + " "
                                + e.getMessage(), e);
                    }
                    if (Files.isDirectory(stage)) {
                        staged.add(key);
                    }
                }
                for (String fill : Schema.FILL_ENGINES) {
                    s.executeUpdate(fill);
                }
                conn.commit();
                committed = true;
                for (String key : staged) {
                    deleteTree(target.runFolder(key));
                    Files.move(staging(target.runFolder(key)), target.runFolder(key));
                }
                return new Outcome(take.size(), total - take.size() - measuredAgain, measuredAgain);
            } catch (SQLException | IOException e) {
                if (!committed) { // once committed, a staged folder not yet swapped in is the only copy beside its row
                    ResultsDatabase.rollBack(conn, e);
                    for (String key : take) {
                        deleteTree(staging(target.runFolder(key)));
                    }
                }
                throw e;
            } finally {
                conn.setAutoCommit(true);
                try (Statement d = conn.createStatement()) {
                    d.execute("DETACH DATABASE src");
                }
                conn.setAutoCommit(false);
            }
        }
    }

    /** Where a run folder is copied before it replaces {@code folder}. */
    private static Path staging(Path folder) {
        return folder.resolveSibling("." + folder.getFileName() + ".merging");
    }

    /** The columns of {@code schema.table}, in order (none when the table does not exist). */
    private static List<String> columns(Statement s, String schema, String table) throws SQLException {
        List<String> out = new ArrayList<>();
        try (ResultSet rs = s.executeQuery("PRAGMA " + schema + ".table_info(" + table + ")")) {
            while (rs.next()) {
                out.add(rs.getString("name"));
            }
        }
        return out;
    }

    /** The index of the name {@code name} in {@code path}, or -1. */
    private static int indexOf(Path path, String name) {
        for (int i = 0; i < path.getNameCount(); i++) {
            if (path.getName(i).toString().equals(name)) {
                return i;
            }
        }
        return -1;
    }

    /** Replaces {@code to} by a copy of {@code from} (nothing when {@code from} does not exist). */
    static void copyTree(Path from, Path to) throws IOException {
        if (!Files.isDirectory(from)) {
            return;
        }
        deleteTree(to);
        Files.createDirectories(to.getParent());
        Files.walkFileTree(from, new SimpleFileVisitor<>() {
            @Override
            public FileVisitResult preVisitDirectory(Path dir, BasicFileAttributes attrs) throws IOException {
                Files.createDirectories(to.resolve(from.relativize(dir).toString()));
                return FileVisitResult.CONTINUE;
            }

            @Override
            public FileVisitResult visitFile(Path file, BasicFileAttributes attrs) throws IOException {
                Files.copy(file, to.resolve(from.relativize(file).toString()), StandardCopyOption.REPLACE_EXISTING);
                return FileVisitResult.CONTINUE;
            }
        });
    }

    /** Deletes a folder tree (nothing when absent). */
    public static void deleteTree(Path p) throws IOException {
        if (!Files.exists(p)) {
            return;
        }
        try (Stream<Path> s = Files.walk(p)) {
            for (Path q : s.sorted(Comparator.reverseOrder()).toList()) {
                Files.deleteIfExists(q);
            }
        }
    }
}
