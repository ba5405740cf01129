package org.jmclbench.tooling.report;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;

/**
 * The report's verification section: the verdicts of {@code ./jmclbench verify}, read from
 * {@code verification.json} beside the results database, as a table (property, policy,
 * verdict, states, seconds). Empty when that file does not exist.
 */
final class VerificationSection {
    static final String FILE = "verification.json";

    private VerificationSection() {
    }

    /** The section's HTML for the results folder, or "" when verify has not run there. */
    static String html(Path resultsDir) throws IOException {
        Path file = resultsDir.resolve(FILE);
        if (!Files.isRegularFile(file)) {
            return "";
        }
        JsonNode doc;
        try {
            doc = new ObjectMapper().readTree(file.toFile());
        } catch (IOException e) {
            return "<section class=\"verification\"><h2>Verification</h2><p>" + ReportPage.escapeHtml(file.toString())
                    + ": not readable (" + ReportPage.escapeHtml(e.getMessage()) + ")</p></section>";
        }
        StringBuilder sb = new StringBuilder();
        sb.append("<section class=\"verification\" id=\"verification\"><h2>Verification</h2>");
        sb.append("<p>Java PathFinder and static checks of the SCJ mission and the rtsj engine (<code>./jmclbench verify</code>, ")
                .append(ReportPage.escapeHtml(doc.path("finished").asText()))
                .append("): ")
                .append(doc.path("passed").asBoolean() ? "every property holds and every seeded bug is caught"
                        : "<strong>some checks failed</strong>")
                .append(".</p>");
        sb.append("<table class=\"sortable\"><thead><tr><th>check</th><th>property</th><th>policy</th><th>kind</th>"
                + "<th>verdict</th><th>states</th><th>seconds</th></tr></thead><tbody>");
        for (JsonNode c : doc.path("checks")) {
            sb.append("<tr class=\"").append(c.path("passed").asBoolean() ? "pass" : "fail").append("\">");
            cell(sb, c.path("id").asText());
            cell(sb, c.path("property").asText());
            cell(sb, c.path("policy").asText());
            cell(sb, c.path("kind").asText() + (c.path("seeded").asBoolean() ? ", seeded bug" : ""));
            cell(sb, c.path("verdict").asText());
            cell(sb, c.has("states") ? c.path("states").asText() : "-");
            cell(sb, c.path("seconds").asText());
            sb.append("</tr>");
        }
        sb.append("</tbody></table></section>");
        return sb.toString();
    }

    private static void cell(StringBuilder sb, String text) {
        sb.append("<td>").append(ReportPage.escapeHtml(text)).append("</td>");
    }
}
