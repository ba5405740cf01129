package org.jmclbench.workload.data;

import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.util.Properties;

import org.jmclbench.core.mcl.Playground;
import org.jmclbench.workload.BadInputException;

/**
 * A dataset's {@code dataset.properties} as docs/FORMATS.md 1.2 specifies it: {@code key=value}
 * lines of printable ASCII, {@code #} or {@code !} comments, no escapes or continuations (not
 * {@link Properties#load}, whose extra syntax the C reader does not share). Read the same way
 * by native/src/dataset.c.
 */
public final class DatasetMetadata {
    /** The most beacons a field has (the C baseline's fixed array). */
    public static final int MAX_BEACONS = 32;
    /** The longest scenario name, in characters. */
    public static final int MAX_SCENARIO = 127;

    /** Every key and value read, the last of a repeated key winning. */
    public final Properties properties;
    /** The field: the thesis's, with what the file sets. */
    public final Playground playground;
    /** Whether the file sets the start pose (all three of start.x, start.y, start.theta). */
    public final boolean startKnown;
    public final double startX;
    public final double startY;
    public final double startTheta;

    private DatasetMetadata(Properties properties, Playground playground, boolean startKnown, double startX,
            double startY, double startTheta) {
        this.properties = properties;
        this.playground = playground;
        this.startKnown = startKnown;
        this.startX = startX;
        this.startY = startY;
        this.startTheta = startTheta;
    }

    /** No file: the thesis's field, the start pose from the ground truth. */
    public static DatasetMetadata none() {
        return new DatasetMetadata(new Properties(), Playground.thesis(), false, 0, 0, 0);
    }

    private static final String[] NUMERIC = {"playground.width", "playground.height", "start.x", "start.y",
        "start.theta"};

    /** Reads the file from {@code in}; {@code name} is what messages call it. */
    public static DatasetMetadata read(InputStream in, String name) throws BadInputException {
        Playground thesis = Playground.thesis();
        Properties props = new Properties();
        double[] numbers = {thesis.width, thesis.height, 0, 0, 0};
        boolean[] has = new boolean[NUMERIC.length];
        double[][] beacons = {thesis.beaconX, thesis.beaconY};
        DataGrammar.Lines lines = new DataGrammar.Lines(in);
        int lineNo = 0;
        try {
            while (lines.next()) {
                lineNo++;
                int from = 0;
                int to = lines.length;
                byte[] b = lines.line;
                while (from < to && DataGrammar.isBlank(b[from])) {
                    from++;
                }
                while (to > from && DataGrammar.isBlank(b[to - 1])) {
                    to--;
                }
                if (from == to || b[from] == '#' || b[from] == '!') {
                    continue;
                }
                property(b, from, to, name, lineNo, props, numbers, has, beacons);
            }
        } catch (IOException e) {
            throw new BadInputException(name + ": cannot read");
        }
        boolean any = has[2] || has[3] || has[4];
        if (any && !(has[2] && has[3] && has[4])) {
            throw new BadInputException(name + ": " + (!has[2] ? "start.x" : !has[3] ? "start.y" : "start.theta")
                    + ": missing");
        }
        return new DatasetMetadata(props, new Playground(numbers[0], numbers[1], beacons[0], beacons[1]), any,
                numbers[2], numbers[3], numbers[4]);
    }

    /** One key=value line {@code b[from..to)}, already trimmed and not a comment. */
    private static void property(byte[] b, int from, int to, String name, int lineNo, Properties props,
            double[] numbers, boolean[] has, double[][] beacons) throws BadInputException {
        int eq = -1;
        for (int i = from; i < to; i++) {
            int c = b[i] & 0xff;
            if ((c < 0x20 && c != '\t') || c >= 0x7f) {
                throw BadInputException.atLine(name, lineNo, "not printable ASCII: byte 0x" + DataGrammar.hex(c));
            }
            if (c == '=' && eq < 0) {
                eq = i;
            }
        }
        int keyEnd = eq;
        while (keyEnd > from && DataGrammar.isBlank(b[keyEnd - 1])) {
            keyEnd--;
        }
        if (eq < 0 || keyEnd == from) {
            throw BadInputException.atLine(name, lineNo, "expected key=value");
        }
        int v = eq + 1;
        while (v < to && DataGrammar.isBlank(b[v])) {
            v++;
        }
        String key = new String(b, from, keyEnd - from, StandardCharsets.ISO_8859_1);
        String value = new String(b, v, to - v, StandardCharsets.ISO_8859_1);
        if (key.equals("scenario") && value.length() > MAX_SCENARIO) {
            throw BadInputException.atLine(name, lineNo, "scenario: longer than " + MAX_SCENARIO + " characters");
        }
        if (key.equals("beacons")) {
            double[][] parsed = beacons(b, v, to);
            if (parsed == null) {
                throw BadInputException.atLine(name, lineNo, "beacons: expected x,y;x,y;... (1 to " + MAX_BEACONS
                        + " beacons)");
            }
            beacons[0] = parsed[0];
            beacons[1] = parsed[1];
        }
        for (int k = 0; k < NUMERIC.length; k++) {
            if (!key.equals(NUMERIC[k])) {
                continue;
            }
            double[] out = new double[1];
            int r = DataGrammar.parseNumber(b, v, to - v, out);
            if (r != DataGrammar.NUM_OK) {
                throw BadInputException.atLine(name, lineNo, key + ": " + DataGrammar.numberProblem(r, b, v, to - v));
            }
            if (k < 2 && !(out[0] > 0)) {
                throw BadInputException.atLine(name, lineNo, key + ": must be positive");
            }
            numbers[k] = out[0];
            has[k] = true;
        }
        props.setProperty(key, value);
    }

    /** {@code x,y;x,y;...} in {@code b[from..to)}, blanks around numbers allowed; null when malformed. */
    private static double[][] beacons(byte[] b, int from, int to) {
        double[] xs = new double[MAX_BEACONS];
        double[] ys = new double[MAX_BEACONS];
        double[] out = new double[1];
        int n = 0;
        int p = from;
        for (;;) {
            int pairEnd = p;
            while (pairEnd < to && b[pairEnd] != ';') {
                pairEnd++;
            }
            int comma = p;
            while (comma < pairEnd && b[comma] != ',') {
                comma++;
            }
            if (comma == pairEnd || n == MAX_BEACONS) {
                return null;
            }
            if (!trimmedNumber(b, p, comma, out)) {
                return null;
            }
            xs[n] = out[0];
            if (!trimmedNumber(b, comma + 1, pairEnd, out)) {
                return null;
            }
            ys[n] = out[0];
            n++;
            if (pairEnd == to) {
                break;
            }
            p = pairEnd + 1;
        }
        return new double[][] {java.util.Arrays.copyOf(xs, n), java.util.Arrays.copyOf(ys, n)};
    }

    private static boolean trimmedNumber(byte[] b, int from, int to, double[] out) {
        while (from < to && DataGrammar.isBlank(b[from])) {
            from++;
        }
        while (to > from && DataGrammar.isBlank(b[to - 1])) {
            to--;
        }
        return DataGrammar.parseNumber(b, from, to - from, out) == DataGrammar.NUM_OK;
    }
}
