package org.jmclbench.tooling.report;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;

/** A run's series ({@code {"columns": [...], "rows": [[...], ...]}}) with columns found by name. */
final class SeriesTable {

    /** Series are mostly numbers: Jackson's fast double parser (FastDoubleParser) halves the report's time. */
    static final ObjectMapper JSON = new ObjectMapper(com.fasterxml.jackson.core.JsonFactory.builder()
            .enable(com.fasterxml.jackson.core.StreamReadFeature.USE_FAST_DOUBLE_PARSER).build());

    private final List<String> columns;
    private final JsonNode rows;

    private SeriesTable(List<String> columns, JsonNode rows) {
        this.columns = columns;
        this.rows = rows;
    }

    /** Parses a series; null when absent or not of the documented shape. */
    static SeriesTable parse(String json) {
        if (json == null) {
            return null;
        }
        try {
            JsonNode root = JSON.readTree(json);
            JsonNode cols = root.get("columns");
            JsonNode rows = root.get("rows");
            if (cols == null || !cols.isArray() || rows == null || !rows.isArray()) {
                return null;
            }
            List<String> names = new ArrayList<>();
            cols.forEach(c -> names.add(normalise(c.asText())));
            return new SeriesTable(names, rows);
        } catch (Exception e) {
            return null;
        }
    }

    private static String normalise(String name) {
        return name.toLowerCase(Locale.ROOT).replaceAll("[^a-z0-9]", "");
    }

    /** Index of the first column named like one of the candidates (case and punctuation ignored), or -1. */
    int column(String... candidates) {
        for (String c : candidates) {
            int i = columns.indexOf(normalise(c));
            if (i >= 0) {
                return i;
            }
        }
        return -1;
    }

    int size() {
        return rows.size();
    }

    /** The text at a row and column; empty when missing. */
    String text(int row, int column) {
        JsonNode r = rows.get(row);
        if (r == null || column < 0 || column >= r.size() || r.get(column).isNull()) {
            return "";
        }
        return r.get(column).asText();
    }

    /** The value at a row and column; NaN when missing or not a number. */
    double value(int row, int column) {
        JsonNode r = rows.get(row);
        if (r == null || column < 0 || column >= r.size() || !r.get(column).isNumber()) {
            return Double.NaN;
        }
        return r.get(column).asDouble();
    }

    /**
     * Points (x * xScale, y * yScale) of two columns, evenly down-sampled to at most
     * {@code maxPoints} rows; rows with a missing value are left out.
     */
    List<double[]> points(int xCol, double xScale, int yCol, double yScale, int maxPoints) {
        List<double[]> out = new ArrayList<>();
        if (xCol < 0 || yCol < 0) {
            return out;
        }
        int n = size();
        double step = Math.max(1.0, (double) n / maxPoints);
        for (double d = 0; d < n; d += step) {
            int i = (int) d;
            double x = value(i, xCol);
            double y = value(i, yCol);
            if (Double.isFinite(x) && Double.isFinite(y)) {
                out.add(new double[] {round(x * xScale), round(y * yScale)});
            }
        }
        return out;
    }

    /**
     * Points like {@link #points} but each of at most {@code maxPoints} buckets keeps its
     * largest y, so that the latency peaks (what a real-time chart is about) survive.
     */
    List<double[]> peakPoints(int xCol, double xScale, int yCol, double yScale, int maxPoints) {
        List<double[]> out = new ArrayList<>();
        if (xCol < 0 || yCol < 0) {
            return out;
        }
        int n = size();
        int bucket = Math.max(1, (n + maxPoints - 1) / maxPoints);
        for (int i = 0; i < n; i += bucket) {
            double bx = Double.NaN;
            double by = Double.NEGATIVE_INFINITY;
            for (int k = i; k < Math.min(n, i + bucket); k++) {
                double x = value(k, xCol);
                double y = value(k, yCol);
                if (Double.isFinite(x) && Double.isFinite(y) && y > by) {
                    bx = x;
                    by = y;
                }
            }
            if (Double.isFinite(bx)) {
                out.add(new double[] {round(bx * xScale), round(by * yScale)});
            }
        }
        return out;
    }

    /** Six significant digits are plenty for a chart and keep the inlined data small. */
    static double round(double v) {
        if (v == 0 || !Double.isFinite(v)) {
            return v;
        }
        double scale = Math.pow(10, 5 - Math.floor(Math.log10(Math.abs(v))));
        return Math.round(v * scale) / scale;
    }
}
