package org.jmclbench.workload.conformance;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.ArrayList;
import java.util.List;

/** One conformance vector file (conformance/README.md): its data lines as tokens, with line numbers for messages. */
final class VectorFile {
    /** A data line: its tokens and where it came from. */
    static final class Line {
        final String where;
        final String[] tokens;

        Line(String where, String[] tokens) {
            this.where = where;
            this.tokens = tokens;
        }

        String kind() {
            return tokens[0];
        }

        long hex64(int i) {
            return Long.parseUnsignedLong(tokens[i], 16);
        }

        double hexDouble(int i) {
            return Double.longBitsToDouble(hex64(i));
        }

        double dec(int i) {
            return Double.parseDouble(tokens[i]);
        }

        int integer(int i) {
            return Integer.parseInt(tokens[i]);
        }

        @Override
        public String toString() {
            return where;
        }
    }

    final List<Line> lines = new ArrayList<>();

    private VectorFile() {
    }

    /** The project's conformance folder, found upwards from the working directory (the module folder under Maven). */
    static Path folder() {
        Path dir = Paths.get("").toAbsolutePath();
        while (dir != null) {
            Path c = dir.resolve("conformance");
            if (Files.isRegularFile(c.resolve("make_vectors.py"))) {
                return c;
            }
            dir = dir.getParent();
        }
        throw new IllegalStateException("conformance/make_vectors.py not found above " + Paths.get("").toAbsolutePath());
    }

    /** The project's root folder. */
    static Path projectHome() {
        return folder().getParent();
    }

    static VectorFile read(String name) throws IOException {
        Path p = folder().resolve(name);
        VectorFile f = new VectorFile();
        List<String> text = Files.readAllLines(p, StandardCharsets.US_ASCII);
        for (int i = 0; i < text.size(); i++) {
            String s = text.get(i).trim();
            if (s.isEmpty() || s.startsWith("#")) {
                continue;
            }
            f.lines.add(new Line(name + ":" + (i + 1), s.split(" +")));
        }
        if (f.lines.isEmpty()) {
            throw new IllegalStateException(p + ": no vectors");
        }
        return f;
    }

    /** The difference of two angles on the circle, in [0, pi]. */
    static double circularDistance(double a, double b) {
        double d = Math.abs(a - b) % (2 * Math.PI);
        return Math.min(d, 2 * Math.PI - d);
    }
}
