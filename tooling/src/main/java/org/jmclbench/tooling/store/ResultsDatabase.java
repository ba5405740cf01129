package org.jmclbench.tooling.store;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.channels.FileChannel;
import java.nio.channels.FileLock;
import java.nio.channels.OverlappingFileLockException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.sql.Connection;
import java.sql.DriverManager;
import java.sql.ResultSet;
import java.sql.SQLException;
import java.sql.Statement;
import java.util.HashSet;
import java.util.Set;

import org.jmclbench.tooling.cli.BadUsageException;
import org.jmclbench.tooling.cli.OutputPaths;
import org.sqlite.SQLiteConfig;
import org.sqlite.SQLiteJDBCLoader;

/**
 * The one way a results database (docs/FORMATS.md section 5) is opened, to read it (report,
 * compare, a merge's sources) or to write it (matrix, quick, evaluate, a merge's target).
 *
 * <p>Before anything is written the file is checked: it must be an SQLite file that passes
 * SQLite's quick integrity check (a truncated or corrupt file does not), hold the {@code runs}
 * table, and carry a schema version ({@code PRAGMA user_version}) from {@link Schema#OLDEST}
 * to {@link Schema#VERSION}. Anything else is a {@link BadUsageException} naming the file
 * (exit code 2) and the file is left as it was. A writer also holds {@code FILE.lock} while it is
 * open, so a second writer on the same store is refused rather than interleaved; opening to
 * write creates a missing store and migrates an older one in place.
 */
public final class ResultsDatabase implements AutoCloseable {

    /** How long a statement waits for another process's transaction (a reader during a commit). */
    static final int BUSY_TIMEOUT_MS = 10_000;

    private final Path file;
    private final Connection connection;
    private final FileChannel lockChannel;

    private ResultsDatabase(Path file, Connection connection, FileChannel lockChannel) {
        this.file = file;
        this.connection = connection;
        this.lockChannel = lockChannel;
    }

    /**
     * Opens an existing store read-only.
     *
     * @param option the option that named the file, for the message ({@code --db}); null when a positional argument
     * @throws BadUsageException when the file is missing or is not a store this tool reads
     */
    public static ResultsDatabase openToRead(Path file, String option) {
        Path abs = file.toAbsolutePath().normalize();
        String where = where(option, file);
        if (!Files.isRegularFile(abs)) {
            throw new BadUsageException(where + "no such database");
        }
        SQLiteConfig config = new SQLiteConfig();
        config.setReadOnly(true);
        config.setBusyTimeout(BUSY_TIMEOUT_MS);
        Connection c = connect(abs, config, where, "not a jmclbench results store");
        try {
            check(c, where, "not a jmclbench results store", false);
        } catch (BadUsageException e) {
            closeQuietly(c);
            throw e;
        }
        return new ResultsDatabase(abs, c, null);
    }

    /**
     * Opens the store to write, creating it (and its folder) when absent, migrating an older schema
     * version in place, and holding its lock until {@link #close}.
     *
     * @throws BadUsageException when the file is not a store this tool writes, when its folder cannot be
     *                           written, or when another process has it open to write
     */
    public static ResultsDatabase openToWrite(Path file, String option) {
        Path abs = file.toAbsolutePath().normalize();
        String where = where(option, file);
        String refusal = "not a usable results store";
        refuseItsPlace(abs, where, refusal);
        FileChannel lock = lock(abs, where);
        try {
            SQLiteConfig config = new SQLiteConfig();
            config.setBusyTimeout(BUSY_TIMEOUT_MS);
            Connection c = connect(abs, config, where, refusal);
            try {
                boolean fresh = check(c, where, refusal, true);
                migrate(c, fresh);
            } catch (BadUsageException e) {
                closeQuietly(c);
                throw e;
            } catch (SQLException e) {
                closeQuietly(c);
                throw new BadUsageException(where + refusal + " (" + oneLine(e.getMessage()) + ")");
            }
            return new ResultsDatabase(abs, c, lock);
        } catch (RuntimeException e) {
            closeQuietly(lock);
            throw e;
        }
    }

    /**
     * Refuses, as {@link #openToWrite} would, a store that cannot be opened to write, creating and changing
     * nothing (no folder, no lock, no migration): what a dry run checks. A store another process is writing
     * is not refused, for the run itself may come after that one has ended.
     *
     * @throws BadUsageException when the file is not a store this tool writes or its folder cannot be made
     */
    public static void checkToWrite(Path file, String option) {
        Path abs = file.toAbsolutePath().normalize();
        String where = where(option, file);
        String refusal = "not a usable results store";
        refuseItsPlace(abs, where, refusal);
        if (!Files.exists(abs)) {
            return; // to be created
        }
        SQLiteConfig config = new SQLiteConfig();
        config.setReadOnly(true);
        config.setBusyTimeout(BUSY_TIMEOUT_MS);
        Connection c = connect(abs, config, where, refusal);
        try {
            check(c, where, refusal, true);
        } finally {
            closeQuietly(c);
        }
    }

    /** Refuses a store whose folder cannot be made or written, or that is itself a folder. */
    private static void refuseItsPlace(Path abs, String where, String refusal) {
        String why = OutputPaths.whyNotAFolder(abs.getParent());
        if (why != null) {
            throw new BadUsageException(where + "cannot write there (" + why + ")");
        }
        if (Files.isDirectory(abs)) {
            throw new BadUsageException(where + refusal + " (a folder)");
        }
    }

    /** {@code option: file: } or {@code file: }, the start of every message about the file. */
    private static String where(String option, Path file) {
        return (option == null ? "" : option + ": ") + file + ": ";
    }

    private static Connection connect(Path abs, SQLiteConfig config, String where, String refusal) {
        loadSqlite();
        try {
            return DriverManager.getConnection("jdbc:sqlite:" + abs, config.toProperties());
        } catch (SQLException e) {
            throw new BadUsageException(where + refusal + " (" + oneLine(e.getMessage()) + ")");
        }
    }

    /**
     * Loads SQLite's native library, which the driver first copies to the temporary folder: on a full disk
     * that fails, and the failure is the machine's (exit 1), not the database file's (bad input).
     */
    private static void loadSqlite() {
        try {
            SQLiteJDBCLoader.initialize();
        } catch (Exception | LinkageError e) {
            throw new UncheckedIOException(new IOException("cannot load SQLite's native library (copied to "
                    + System.getProperty("org.sqlite.tmpdir", System.getProperty("java.io.tmpdir")) + "; is that disk full?): "
                    + oneLine(e.getMessage()), e));
        }
    }

    /**
     * Takes {@code FILE.lock} (creating the folder) without waiting: a second matrix on one store would
     * interleave its runs with the first's and disturb their timing.
     */
    private static FileChannel lock(Path abs, String where) {
        Path lockFile = abs.resolveSibling(abs.getFileName() + ".lock");
        FileChannel ch;
        try {
            Files.createDirectories(abs.getParent());
            ch = FileChannel.open(lockFile, StandardOpenOption.CREATE, StandardOpenOption.WRITE);
        } catch (IOException e) {
            throw new BadUsageException(where + "cannot write there (" + e.getClass().getSimpleName() + ")");
        }
        FileLock held;
        try {
            held = ch.tryLock();
        } catch (IOException | OverlappingFileLockException e) {
            held = null;
        }
        if (held == null) {
            closeQuietly(ch);
            throw new BadUsageException(where + "another matrix or merge is writing to it (" + lockFile.getFileName()
                    + " is held); wait for it to end or use another database");
        }
        return ch;
    }

    /**
     * Checks that {@code c} is a store this tool knows, before anything is written to it.
     *
     * @param mayBeNew whether a file without tables (new, or empty) is acceptable: then it is to be created
     * @return whether the file is new
     */
    private static boolean check(Connection c, String where, String refusal, boolean mayBeNew) {
        try (Statement s = c.createStatement()) {
            Set<String> tables = new HashSet<>();
            try (ResultSet rs = s.executeQuery("SELECT name FROM sqlite_master WHERE type = 'table'")) {
                while (rs.next()) {
                    tables.add(rs.getString(1));
                }
            }
            int version;
            try (ResultSet rs = s.executeQuery("PRAGMA user_version")) {
                version = rs.next() ? rs.getInt(1) : 0;
            }
            if (tables.isEmpty() && version == 0 && mayBeNew) {
                return true;
            }
            try (ResultSet rs = s.executeQuery("PRAGMA quick_check")) {
                String verdict = rs.next() ? rs.getString(1) : "no answer";
                if (!"ok".equals(verdict)) {
                    throw new BadUsageException(where + refusal + " (corrupt: " + oneLine(verdict) + ")");
                }
            }
            if (!tables.contains("runs")) {
                throw new BadUsageException(where + refusal + " (no runs table)");
            }
            for (String[] t : Schema.REQUIRED) {
                Set<String> have = new HashSet<>();
                try (ResultSet rs = s.executeQuery("PRAGMA table_info(" + t[0] + ")")) {
                    while (rs.next()) {
                        have.add(rs.getString("name"));
                    }
                }
                for (int i = 1; i < t.length; i++) {
                    if (!have.contains(t[i])) {
                        throw new BadUsageException(where + refusal + (have.isEmpty() ? " (no " + t[0] + " table)"
                                : " (table " + t[0] + " has no column " + t[i] + ")"));
                    }
                }
            }
            if (version > Schema.VERSION) {
                throw new BadUsageException(where + refusal + " (schema version " + version + " is newer than this tool's, "
                        + Schema.VERSION + ": a newer jmclbench wrote it)");
            }
            if (version < Schema.OLDEST) {
                throw new BadUsageException(where + refusal + " (schema version " + version + "; this tool knows "
                        + Schema.OLDEST + " to " + Schema.VERSION + ")");
            }
            return false;
        } catch (SQLException e) {
            // SQLite says "file is not a database" or "database disk image is malformed"
            throw new BadUsageException(where + refusal + " (" + oneLine(e.getMessage()) + ")");
        }
    }

    /** Creates the tables of a new store or adds what an older version lacks, in one transaction. */
    private static void migrate(Connection c, boolean fresh) throws SQLException {
        c.setAutoCommit(false);
        try (Statement s = c.createStatement()) {
            for (String ddl : Schema.CREATE) {
                s.execute(ddl);
            }
            if (!fresh) {
                Set<String> have = new HashSet<>();
                try (ResultSet rs = s.executeQuery("PRAGMA table_info(runs)")) {
                    while (rs.next()) {
                        have.add(rs.getString("name"));
                    }
                }
                for (String[] col : Schema.ADDED_RUN_COLUMNS) {
                    if (!have.contains(col[0])) {
                        s.execute("ALTER TABLE runs ADD COLUMN " + col[0] + " " + col[1]); // an older store: migrate
                    }
                }
                for (String fill : Schema.FILL_ENGINES) {
                    s.execute(fill);
                }
            }
            s.execute("PRAGMA user_version = " + Schema.VERSION);
            c.commit();
        } catch (SQLException e) {
            rollBack(c, e);
            throw e;
        }
    }

    /**
     * Rolls back the transaction that {@code cause} ended. On a full disk SQLite has already rolled it back
     * itself, and rolling back again fails ("no transaction is active"): that failure must not hide the cause.
     */
    static void rollBack(Connection c, Exception cause) {
        try {
            c.rollback();
        } catch (SQLException e) {
            cause.addSuppressed(e);
        }
    }

    /** The database file, absolute. */
    public Path file() {
        return file;
    }

    /** The folder holding the database; run folders are relative to it. */
    public Path baseDir() {
        return file.getParent();
    }

    Connection connection() {
        return connection;
    }

    /** An SQLite message on one line (they can hold the statement). */
    static String oneLine(String s) {
        return s == null ? "" : s.replaceAll("\\s+", " ").trim();
    }

    private static void closeQuietly(AutoCloseable c) {
        try {
            c.close();
        } catch (Exception e) {
            // already failing: the first problem is the one reported
        }
    }

    /** Closes the connection, then gives up the lock. */
    @Override
    public void close() throws SQLException {
        try {
            connection.close();
        } finally {
            if (lockChannel != null) {
                closeQuietly(lockChannel);
            }
        }
    }
}
