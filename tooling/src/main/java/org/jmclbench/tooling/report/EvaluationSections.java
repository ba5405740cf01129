package org.jmclbench.tooling.report;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Collectors;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;

import static org.jmclbench.tooling.report.EvaluationData.separationSentence;

/**
 * What the evaluation's section writers share: the numbers ({@link EvaluationData}), the
 * Markdown text being written, its figures and the findings the conclusions repeat. The text
 * lives here, the numbers in {@link EvaluationData}.
 */
abstract class EvaluationSections {
    final EvaluationData data;
    final ReportModel model;
    final JsonNode verification;
    final Path verificationFile;
    private final String figureLink;
    final ChartExporter charts;
    private final StringBuilder md;
    /** One line per claim, with its section, repeated by the conclusions. */
    final List<String> findings;
    /** Every test of two cells the sections made, in order: section 2.14 makes each again on the previous evaluation. */
    final List<Test> tests;

    EvaluationSections(EvaluationData data, Path document, Path figures, Path verificationFile) throws IOException {
        this.data = data;
        this.model = data.model;
        Path base = document.toAbsolutePath().getParent();
        this.figureLink = base.relativize(figures.toAbsolutePath()).toString().replace('\\', '/');
        this.charts = new ChartExporter(figures);
        this.verificationFile = verificationFile;
        this.verification = verificationFile != null && Files.isRegularFile(verificationFile)
                ? new ObjectMapper().readTree(verificationFile.toFile()) : null;
        this.md = new StringBuilder();
        this.findings = new ArrayList<>();
        this.tests = new ArrayList<>();
    }

    /** Another writer of the same document: the same text, figures and findings. */
    EvaluationSections(EvaluationSections document) {
        this.data = document.data;
        this.model = document.model;
        this.verification = document.verification;
        this.verificationFile = document.verificationFile;
        this.figureLink = document.figureLink;
        this.charts = document.charts;
        this.md = document.md;
        this.findings = document.findings;
        this.tests = document.tests;
    }

    /** One test of two cells on a metric, as a section made it. */
    record Test(ReportModel.Cell a, ReportModel.Cell b, Metric metric, Separation.Result result) {
    }

    /** {@link Separation}'s rule applied to two cells' per-run values of a metric, kept among the document's {@link #tests}. */
    Separation.Result separate(ReportModel.Cell a, ReportModel.Cell b, Metric m) {
        Separation.Result r = EvaluationData.separationOf(a, b, m);
        tests.add(new Test(a, b, m, r));
        return r;
    }

    /** Whether two cells differ in a metric, said in {@link EvaluationData#separationSentence}; the test is kept. */
    String separation(ReportModel.Cell a, ReportModel.Cell b, Metric m) {
        return separationSentence(separate(a, b, m), a, b);
    }

    /**
     * The heading of a missCount column in a table whose rows differ in policy: what it counts
     * under each (Metric.missCountJobs), as a late job under skip is a miss it does not count.
     */
    static final String MISS_COUNT_BY_POLICY = "missCount (skip: dropped; terminate: dropped or aborted; queue: late)";

    /** The Markdown written so far. */
    String text() {
        return md.toString();
    }

    /**
     * The document with each section heading naming only the tables and figures the document has:
     * a section left without data ("no run under queue") printed "(Table 1, Figure 1)" and neither.
     */
    static String headingsNamingWhatTheyHave(String doc) {
        Matcher m = HEADING_NUMBERS.matcher(doc);
        StringBuilder out = new StringBuilder();
        while (m.find()) {
            List<String> kept = new ArrayList<>();
            for (String item : m.group(2).split(", ")) {
                // a table's caption starts its line ("Table 1: ..."), a figure's is set in italics ("*Figure 1: ...")
                if (doc.contains("\n" + item + ":") || doc.contains("*" + item + ":")) {
                    kept.add(item);
                }
            }
            m.appendReplacement(out, Matcher.quoteReplacement(m.group(1) + (kept.isEmpty() ? "" : " (" + String.join(", ", kept) + ")")));
        }
        m.appendTail(out);
        return out.toString();
    }

    private static final Pattern HEADING_NUMBERS = Pattern.compile("(?m)^(### .*?) \\(((?:Table|Figure) [0-9a-z]+(?:, (?:Table|Figure) [0-9a-z]+)*)\\)$");

    interface ChartJob {
        void run() throws IOException;
    }

    void figure(String stem, String caption, ChartJob job) throws IOException {
        job.run();
        line("![" + caption + "](" + (figureLink.isEmpty() ? "" : figureLink + "/") + stem + ".svg)");
        line("");
        line("*" + caption + "*");
        line("");
    }

    /** What a figure is drawn from: cells of the dataset under skip, at one particle count or (null) over the sweep. */
    ChartSpecs.Scope scope(Integer particles, List<ReportModel.Cell> cells) {
        return new ChartSpecs.Scope(model, new ChartSpec.Setting(data.dataset, "skip", particles), cells);
    }

    void table(List<String> header, List<List<String>> rows) {
        line("| " + header.stream().map(EvaluationSections::escape).collect(Collectors.joining(" | ")) + " |");
        line("|" + " --- |".repeat(header.size()));
        for (List<String> r : rows) {
            line("| " + r.stream().map(EvaluationSections::escape).collect(Collectors.joining(" | ")) + " |");
        }
        line("");
    }

    /** Table cells come from the store (runtime names, versions): a pipe or markup must not break the table. */
    static String escape(String v) {
        return v.replace("\\", "\\\\").replace("|", "\\|").replace("<", "&lt;").replace(">", "&gt;").replace("\n", " ");
    }

    /** True, having written {@code why} as the section's whole text, when the store has none of the {@code cells} it needs. */
    boolean absent(List<ReportModel.Cell> cells, String why) {
        if (!cells.isEmpty()) {
            return false;
        }
        line(why);
        line("");
        return true;
    }

    void line(String s) {
        md.append(s).append('\n');
    }
}
