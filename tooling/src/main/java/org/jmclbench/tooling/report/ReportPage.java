package org.jmclbench.tooling.report;

import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Map;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import org.jmclbench.tooling.cli.Counts;

import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.SerializationFeature;

/**
 * Writes the self-contained {@code index.html}: the template, the page's CSS and script, Chart.js
 * read from its WebJar on the classpath, and the model as inlined JSON; no external reference.
 */
final class ReportPage {

    /** The Chart.js build inlined into the page (the WebJar's UMD bundle). */
    static final String CHART_JS = "/META-INF/resources/webjars/chart.js/4.4.1/dist/chart.umd.js";

    private ReportPage() {
    }

    static void write(ReportModel model, Path file) throws IOException {
        write(model, file, null);
    }

    /** The page; {@code resultsDir} is where verify's verdicts may be (null: none shown). */
    static void write(ReportModel model, Path file, Path resultsDir) throws IOException {
        Map<String, String> parts = Map.ofEntries(
                Map.entry("VERIFICATION", resultsDir == null ? "" : VerificationSection.html(resultsDir)),
                Map.entry("CSS", resource("report.css")),
                Map.entry("DB", escapeHtml(model.database)),
                Map.entry("RUNS", Counts.of(model.runCount, "run")),
                Map.entry("GENERATED", escapeHtml(model.generatedAt)),
                Map.entry("CODE", escapeHtml(model.codeVersions)),
                Map.entry("DATA", json(model)),
                Map.entry("CHARTJS", inlineScript(chartJs())),
                Map.entry("PLUGINS", inlineScript(resource("report-plugins.js"))),
                Map.entry("CHARTCONFIG", inlineScript(resource("report-chart-config.js"))),
                Map.entry("APP", inlineScript(resource("report.js"))));
        Files.writeString(file, fill(resource("report.html"), parts), StandardCharsets.UTF_8);
    }

    /**
     * Replaces each {@code /*NAME*}{@code /} of the template in one pass, so that text put in
     * (a database name, the data) is never searched for placeholders itself.
     */
    static String fill(String template, Map<String, String> parts) {
        Matcher m = Pattern.compile("/\\*([A-Z]+)\\*/").matcher(template);
        StringBuilder out = new StringBuilder(template.length() + parts.values().stream().mapToInt(String::length).sum());
        while (m.find()) {
            String part = parts.get(m.group(1));
            m.appendReplacement(out, Matcher.quoteReplacement(part == null ? m.group() : part));
        }
        m.appendTail(out);
        return out.toString();
    }

    /** The model as JSON that is safe inside a script element: no '<', '>' or '&' outside escapes. */
    static String json(ReportModel model) throws IOException {
        ObjectMapper mapper = new ObjectMapper();
        mapper.disable(SerializationFeature.FAIL_ON_EMPTY_BEANS);
        String json = mapper.writeValueAsString(model);
        // In JSON these characters only occur inside strings, where \\uXXXX means the same.
        return json.replace("<", "\\u003c").replace(">", "\\u003e").replace("&", "\\u0026");
    }

    /** HTML text escaping for the few strings put into the page on the server side. */
    static String escapeHtml(String s) {
        if (s == null) {
            return "";
        }
        StringBuilder sb = new StringBuilder(s.length());
        for (int i = 0; i < s.length(); i++) {
            char c = s.charAt(i);
            switch (c) {
                case '<' -> sb.append("&lt;");
                case '>' -> sb.append("&gt;");
                case '&' -> sb.append("&amp;");
                case '"' -> sb.append("&quot;");
                case '\'' -> sb.append("&#39;");
                default -> sb.append(c);
            }
        }
        return sb.toString();
    }

    private static String chartJs() throws IOException {
        String js = read(ReportPage.class.getResourceAsStream(CHART_JS), CHART_JS);
        // The source map is not shipped: drop the reference so that nothing is ever fetched.
        return js.replaceAll("(?m)^//# sourceMappingURL=.*$", "");
    }

    /** A script's text cannot contain "</script"; none of ours or Chart.js's does, but make sure. */
    private static String inlineScript(String js) {
        return js.replace("</script", "<\\/script").replace("<!--", "<\\!--");
    }

    private static String resource(String name) throws IOException {
        return read(ReportPage.class.getResourceAsStream(name), name);
    }

    private static String read(InputStream in, String name) throws IOException {
        if (in == null) {
            throw new IOException("missing resource " + name + " (broken build)");
        }
        try (in) {
            return new String(in.readAllBytes(), StandardCharsets.UTF_8);
        }
    }
}
