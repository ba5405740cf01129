package org.jmclbench.tooling.store;

import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.sql.SQLException;
import java.sql.Statement;
import java.util.zip.GZIPInputStream;
import java.util.zip.GZIPOutputStream;
import java.util.zip.ZipException;

import org.jmclbench.tooling.cli.BadUsageException;

/**
 * A results store as a committed file: the evaluation's data (issue: an evaluation a reviewer
 * would accept, "reproducible"). {@link #write} compacts a store ({@code VACUUM INTO}, so no
 * free pages or journal travel with it), leaves out the per-run time series the document never
 * reads ({@link #LEFT_OUT}) and gzips it; {@link #extract} restores it to a scratch folder,
 * where it is opened like any store (and checked like any store: a damaged archive is refused
 * with the file named).
 */
public final class StoreArchive {
    /**
     * The series an archive leaves out: each run's estimated trajectory and deviation over time,
     * which only the report's per-run trajectory and deviation charts draw (the document's
     * deviation is the runs' mean, a metric). They were 60% of the first evaluation's archive
     * (13.6 MB with them, 5.6 MB without), and the document and its figures are the same bytes
     * without them.
     */
    public static final java.util.List<String> LEFT_OUT = java.util.List.of("trajectory", "deviation");

    private StoreArchive() {
    }

    /** Writes {@code db}, compacted and gzipped, to {@code archive}, replacing it only once complete. */
    public static void write(Path db, Path archive) throws IOException {
        Path dir = archive.toAbsolutePath().getParent();
        Files.createDirectories(dir);
        Path compact = Files.createTempFile(dir, ".store", ".db");
        Path partial = Files.createTempFile(dir, ".store", ".gz");
        try {
            Files.delete(compact); // VACUUM INTO wants a new file
            try (ResultsDatabase source = ResultsDatabase.openToRead(db, "--db");
                 Statement s = source.connection().createStatement()) {
                s.execute("VACUUM INTO '" + compact.toString().replace("'", "''") + "'");
            } catch (SQLException e) {
                throw new IOException(db + ": cannot compact the store (" + e.getMessage() + ")", e);
            }
            try (java.sql.Connection c = java.sql.DriverManager.getConnection("jdbc:sqlite:" + compact);
                 Statement s = c.createStatement()) {
                s.executeUpdate("DELETE FROM series WHERE name IN ('" + String.join("', '", LEFT_OUT) + "')");
                s.execute("VACUUM");
            } catch (SQLException e) {
                throw new IOException(db + ": cannot slim the store's copy (" + e.getMessage() + ")", e);
            }
            try (InputStream in = Files.newInputStream(compact);
                 OutputStream out = new GZIPOutputStream(Files.newOutputStream(partial), 1 << 16)) {
                in.transferTo(out);
            }
            Files.move(partial, archive, StandardCopyOption.REPLACE_EXISTING, StandardCopyOption.ATOMIC_MOVE);
        } finally {
            Files.deleteIfExists(compact);
            Files.deleteIfExists(partial);
        }
    }

    /**
     * Restores {@code archive} into {@code dir} as {@code <name without .gz>} and returns it.
     *
     * @param option the option that named the archive, for the message
     * @throws BadUsageException when the archive is missing or not gzip
     */
    public static Path extract(Path archive, Path dir, String option) throws IOException {
        if (!Files.isRegularFile(archive)) {
            throw new BadUsageException(option + ": " + archive + ": no such file (the evaluation's data is written by a run of evaluate)");
        }
        String name = archive.getFileName().toString();
        Path db = dir.resolve(name.endsWith(".gz") ? name.substring(0, name.length() - 3) : name + ".db");
        try (InputStream in = new GZIPInputStream(Files.newInputStream(archive), 1 << 16)) {
            Files.copy(in, db, StandardCopyOption.REPLACE_EXISTING);
        } catch (ZipException | java.io.EOFException e) {
            throw new BadUsageException(option + ": " + archive + ": not a gzip'd results store (" + e.getMessage() + ")");
        }
        return db;
    }
}
