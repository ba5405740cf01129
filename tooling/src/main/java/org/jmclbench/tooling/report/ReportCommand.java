package org.jmclbench.tooling.report;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.Callable;

import org.jmclbench.tooling.cli.BadUsageException;
import org.jmclbench.tooling.cli.Counts;
import org.jmclbench.tooling.cli.OutputPaths;
import org.jmclbench.tooling.store.StoredRuns;

import picocli.CommandLine.Command;
import picocli.CommandLine.Option;

/** Builds the HTML report (charts, comparison tables, SVG/PNG exports) from the results database. */
@Command(name = "report", mixinStandardHelpOptions = true,
        header = "Builds the report (a page and its charts) from the results store.",
        description = {"Builds the report from the results database: a self-contained index.html (works "
                + "offline from file://) with the comparison tables and charts, and every chart as "
                + "SVG and PNG in charts/. See docs/REPORT.md.",
                ""})
public final class ReportCommand implements Callable<Integer> {

    @Option(names = "--db", paramLabel = "FILE", description = "results database (default: ${DEFAULT-VALUE})")
    Path db = Path.of("results", "results.db");

    @Option(names = "--out", paramLabel = "DIR", description = "report folder (default: report/ beside the database, results/report)")
    Path out;

    @Option(names = "--no-export", description = "skip the SVG/PNG export of the charts (the page alone)")
    boolean noExport;

    @Override
    public Integer call() throws BadUsageException, IOException {
        build(db, out, !noExport);
        return 0;
    }

    /**
     * Builds the report of the database {@code db} into {@code out} ({@code report/} beside the database when
     * null), the charts' SVG/PNG files too when {@code export}; {@code quick} calls this after its matrix.
     *
     * @return the page written, {@code index.html}
     */
    public static Path build(Path db, Path out, boolean export) throws BadUsageException, IOException {
        System.setProperty("java.awt.headless", "true");
        long t0 = System.nanoTime();
        if (out == null) {
            Path parent = db.toAbsolutePath().getParent();
            out = parent == null ? Path.of("report") : parent.resolve("report");
        }
        // a folder that cannot be made would fail the report only after the store is read and the charts built
        OutputPaths.checkFolder(out, "--out");
        // and what goes in it: a folder named index.html, or a file named charts, failed the report (exit 1)
        // after the page was written, which then stood as if the report were whole
        if (Files.isDirectory(out.resolve("index.html"))) {
            throw BadUsageException.ofOption("--out", out.resolve("index.html") + ": a folder, where the page goes");
        }
        if (export) {
            OutputPaths.checkFolder(out.resolve("charts"), "--out");
        }
        Path resultsDir = db.toAbsolutePath().getParent();
        ReportModel model;
        try (StoredRuns store = StoredRuns.open(db, "--db")) {
            model = ReportModel.build(store, AbortBounds.read(resultsDir.resolve(VerificationSection.FILE)), ReportCommand::progress);
        }
        Files.createDirectories(out);
        Path index = out.resolve("index.html");
        ReportPage.write(model, index, resultsDir);
        progress("wrote " + index);
        if (export) {
            int files = new ChartExporter(out.resolve("charts")).exportAll(model.charts, ReportCommand::progress);
            progress("wrote " + files + " chart files to " + out.resolve("charts"));
        }
        System.out.printf(java.util.Locale.ROOT, "report: %s (%s, %.1f s)%n", index, Counts.of(model.runCount, "run"),
                (System.nanoTime() - t0) / 1e9);
        return index;
    }

    private static void progress(String line) {
        System.err.println("report: " + line);
    }

    /** "done/total" with the time left, estimated from the pace so far. */
    static String eta(int done, int total, long startNanos) {
        double elapsed = (System.nanoTime() - startNanos) / 1e9;
        double left = done == 0 ? Double.NaN : elapsed / done * (total - done);
        return done + "/" + total + (done < total && Double.isFinite(left)
                ? String.format(java.util.Locale.ROOT, ", about %.0f s left", Math.ceil(left)) : "");
    }
}
