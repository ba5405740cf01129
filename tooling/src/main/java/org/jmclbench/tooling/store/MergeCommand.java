package org.jmclbench.tooling.store;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.Callable;

import org.jmclbench.tooling.cli.BadUsageException;

import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;

/** Merges results databases (machines, shards) into one, keeping every run once. */
@Command(name = "merge", mixinStandardHelpOptions = true,
        description = {"Merges results databases into one: every run once (by run key; an ok run wins over a",
                "failed one), with its run folder copied. Example: merge A.db B.db --into C.db"})
public final class MergeCommand implements Callable<Integer> {

    @Parameters(arity = "1..*", paramLabel = "DB", description = "databases to merge")
    List<Path> sources;

    @Option(names = "--into", required = true, paramLabel = "DB", description = "the database to merge into (created when absent)")
    Path into;

    @Override
    public Integer call() throws Exception {
        for (Path s : sources) {
            if (!Files.isRegularFile(s)) {
                throw new BadUsageException(s + ": no such database");
            }
            checkSchema(s); // every source is checked before the target is touched
        }
        try (RunRecorder target = RunRecorder.open(into)) {
            for (Path s : sources) {
                StoreMerger.Outcome o;
                try {
                    o = StoreMerger.merge(target, s);
                } catch (java.io.IOException | java.sql.SQLException e) {
                    throw new BadUsageException(s + ": " + e.getMessage());
                }
                System.out.println(s + ": " + o.taken() + " runs merged, " + o.kept() + " already in " + into);
            }
        }
        return 0;
    }

    /** A source must be a results store of a schema version this tool reads. */
    private static void checkSchema(Path db) throws BadUsageException {
        try (java.sql.Connection c = java.sql.DriverManager.getConnection("jdbc:sqlite:file:" + db.toAbsolutePath() + "?mode=ro");
             java.sql.Statement st = c.createStatement();
             java.sql.ResultSet rs = st.executeQuery("PRAGMA user_version")) {
            int v = rs.next() ? rs.getInt(1) : 0;
            try (java.sql.ResultSet t = st.executeQuery("SELECT count(*) FROM sqlite_master WHERE name = 'runs'")) {
                if (v < Schema.OLDEST || v > Schema.VERSION || !t.next() || t.getInt(1) != 1) {
                    throw new BadUsageException(db + ": not a jmclbench results store (schema version " + v + ")");
                }
            }
        } catch (java.sql.SQLException e) {
            throw new BadUsageException(db + ": not a jmclbench results store (" + e.getMessage() + ")");
        }
    }
}
