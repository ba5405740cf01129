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
 * Run folders are copied with their rows.
 */
public final class StoreMerger {

    /** How many runs a merge took from one source and how many it left because the target had them. */
    public record Outcome(int taken, int kept) {
    }

    private StoreMerger() {
    }

    /** Merges {@code source} into {@code target}. */
    public static Outcome merge(ResultStore target, Path source) throws SQLException, IOException {
        Path src = source.toAbsolutePath().normalize();
        if (!Files.isRegularFile(src)) {
            throw new IOException(source + ": no such database");
        }
        if (src.equals(target.dbFile())) {
            return new Outcome(0, 0);
        }
        var conn = target.connection();
        try (Statement s = conn.createStatement()) {
            conn.commit();
            conn.setAutoCommit(true); // ATTACH cannot run inside a transaction
            try (PreparedStatement ps = conn.prepareStatement("ATTACH DATABASE ? AS src")) {
                ps.setString(1, src.toString());
                ps.execute();
            }
            conn.setAutoCommit(false);
            try {
                int version;
                try (ResultSet rs = s.executeQuery("PRAGMA src.user_version")) {
                    version = rs.next() ? rs.getInt(1) : 0;
                }
                if (version != Schema.VERSION) {
                    throw new IOException(source + ": not a jmclbench results store of schema version " + Schema.VERSION
                            + " (user_version " + version + ")");
                }
                s.executeUpdate("INSERT OR IGNORE INTO machines SELECT * FROM src.machines");
                s.executeUpdate("INSERT OR IGNORE INTO matrices SELECT * FROM src.matrices");
                List<String> take = new ArrayList<>();
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
                Path srcBase = src.getParent();
                for (String key : take) {
                    for (String t : Schema.RUN_TABLES) {
                        try (PreparedStatement del = conn.prepareStatement("DELETE FROM main." + t + " WHERE run_key = ?");
                             PreparedStatement ins = conn.prepareStatement("INSERT INTO main." + t + " SELECT * FROM src." + t + " WHERE run_key = ?")) {
                            del.setString(1, key);
                            del.executeUpdate();
                            ins.setString(1, key);
                            ins.executeUpdate();
                        }
                    }
                    copyTree(srcBase.resolve("runs").resolve(key), target.runFolder(key));
                }
                conn.commit();
                return new Outcome(take.size(), total - take.size());
            } catch (SQLException | IOException e) {
                conn.rollback();
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
