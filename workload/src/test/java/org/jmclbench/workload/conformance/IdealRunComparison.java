package org.jmclbench.workload.conformance;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * Two ideal runs' folders held against each other as conformance/README.md states for whole
 * runs: every line of position.txt and covariance.txt and the mean deviations of data.txt
 * within 1e-9 (m, rad; the last column of position.txt, the heading, on the circle), times
 * exact, and summary.json's deadline counts equal. The result names the first difference, so a
 * long run can count disagreements instead of stopping at the first.
 */
final class IdealRunComparison {
    /** The whole-run tolerance of the conformance contract (m, rad). */
    static final double TOL = 1e-9;
    private static final String[] DEVIATIONS = {"deviationXY", "deviationX", "deviationY", "deviationAngle"};
    private static final String[] COUNTS = {"released", "completed", "done", "late", "skipped", "terminated",
        "missCount", "deadlineMisses", "missRatio"};

    /** The first difference beyond the tolerance, or null; with the largest difference seen and the lines compared. */
    final String difference;
    final double largest;
    final int positionLines;

    private IdealRunComparison(String difference, double largest, int positionLines) {
        this.difference = difference;
        this.largest = largest;
        this.positionLines = positionLines;
    }

    /** Compares run folder {@code a} with {@code b} (named in the message); covariance.txt too when cov. */
    static IdealRunComparison of(Path a, String nameA, Path b, String nameB, boolean cov) throws IOException {
        double[] largest = {0};
        String vs = " (" + nameA + ", " + nameB + ")";
        List<double[]> pa = rows(a.resolve("position.txt"));
        String d = lines("position.txt", pa, rows(b.resolve("position.txt")), true, largest);
        if (d == null && cov) {
            d = lines("covariance.txt", rows(a.resolve("covariance.txt")), rows(b.resolve("covariance.txt")), false,
                    largest);
        }
        if (d == null) {
            Map<String, Double> da = keyValues(a.resolve("data.txt"));
            Map<String, Double> db = keyValues(b.resolve("data.txt"));
            for (String k : DEVIATIONS) {
                if (!da.containsKey(k) || !db.containsKey(k)) {
                    d = "data.txt lacks " + k;
                    break;
                }
                double diff = Math.abs(da.get(k) - db.get(k));
                largest[0] = Math.max(largest[0], diff);
                if (!(diff <= TOL)) {
                    d = "data.txt " + k + ": " + da.get(k) + ", " + db.get(k);
                    break;
                }
            }
        }
        if (d == null) {
            String sa = read(a.resolve("summary.json"));
            String sb = read(b.resolve("summary.json"));
            for (String k : COUNTS) {
                List<String> va = jsonNumbers(sa, k);
                List<String> vb = jsonNumbers(sb, k);
                if (va.size() < 3) {
                    d = "summary.json lacks " + k;
                    break;
                }
                if (!va.equals(vb)) {
                    d = "summary.json " + k + ": " + va + ", " + vb;
                    break;
                }
            }
        }
        return new IdealRunComparison(d == null ? null : d + vs, largest[0], pa.size());
    }

    /** The first row of two 'time v1 v2 ...' files beyond the tolerance; the last column an angle when lastIsAngle. */
    private static String lines(String file, List<double[]> a, List<double[]> b, boolean lastIsAngle,
            double[] largest) {
        if (a.size() != b.size()) {
            return file + ": " + a.size() + " and " + b.size() + " lines";
        }
        for (int i = 0; i < a.size(); i++) {
            double[] r = a.get(i);
            double[] s = b.get(i);
            if (r.length != s.length) {
                return file + " row " + (i + 1) + ": " + r.length + " and " + s.length + " columns";
            }
            if (r[0] != s[0]) {
                return file + " row " + (i + 1) + ": times " + r[0] + ", " + s[0];
            }
            for (int c = 1; c < r.length; c++) {
                double d = lastIsAngle && c == r.length - 1 ? VectorFile.circularDistance(r[c], s[c])
                        : Math.abs(r[c] - s[c]);
                largest[0] = Math.max(largest[0], d);
                if (!(d <= TOL)) {
                    return file + " row " + (i + 1) + " column " + c + ": " + r[c] + ", " + s[c]
                            + " (the implementations diverge here)";
                }
            }
        }
        return null;
    }

    private static List<double[]> rows(Path p) throws IOException {
        List<double[]> rows = new ArrayList<>();
        for (String line : Files.readAllLines(p, StandardCharsets.UTF_8)) {
            line = line.trim();
            if (line.isEmpty() || line.startsWith("#")) {
                continue;
            }
            String[] t = line.split("\\s+");
            double[] v = new double[t.length];
            for (int i = 0; i < t.length; i++) {
                v[i] = Double.parseDouble(t[i]);
            }
            rows.add(v);
        }
        return rows;
    }

    private static Map<String, Double> keyValues(Path p) throws IOException {
        Map<String, Double> m = new HashMap<>();
        for (String line : Files.readAllLines(p, StandardCharsets.UTF_8)) {
            String[] t = line.trim().split("\\s+");
            if (t.length == 2 && !t[0].startsWith("#")) {
                try {
                    m.put(t[0], Double.parseDouble(t[1]));
                } catch (NumberFormatException e) {
                    // not a number-valued key
                }
            }
        }
        return m;
    }

    /** Every value of the key {@code "name": <number>} in the text, in order, as numbers' texts normalised. */
    private static List<String> jsonNumbers(String json, String name) {
        List<String> out = new ArrayList<>();
        Matcher m = Pattern.compile("\"" + name + "\": (-?[0-9.eE+-]+)").matcher(json);
        while (m.find()) {
            out.add(Double.toString(Double.parseDouble(m.group(1))));
        }
        return out;
    }

    /** A file's text, or the exception's when it cannot be read (for messages). */
    static String read(Path p) {
        try {
            return new String(Files.readAllBytes(p), StandardCharsets.UTF_8);
        } catch (IOException e) {
            return e.toString();
        }
    }
}
