package org.jmclbench.workload.data;

import java.io.ByteArrayOutputStream;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Random;

/**
 * Data files for the differential test: generated near the grammar of docs/FORMATS.md 1.1 and
 * 1.2 (numbers in every spelling the grammar has, and the hard ones to round), then mutated
 * at the bytes both readers could disagree on (CR, NUL, VT, a byte-order mark, signs, exponents).
 */
final class DataMutator {
    /** Numbers whose reading is hard to get right within the data's range (VALUE_MAX): halfway cases, subnormals, its edges. */
    private static final String[] HARD = {"0", "-0", "+0.", ".0", "0.0e0", "4.9e-324", "2.4703282292062327e-324",
        "2.4703282292062328e-324", "2.2250738585072011e-308", "2.2250738585072012e-308",
        "0.1000000000000000055511151231257827021181583404541015625", "1e-400", "1e0000000000000000000001",
        "1e-99999999999999999999", "123456789012345678901234567890e-30", "0.3", "5e-324",
        "3.0517578125e-05", "1.00000000000000011102230246251565404236316680908203125", "1.", ".5", "+.5", "-.5e+3",
        "1E+2", "1e-2", "1e9", "-1000000000", "1.00000000000000000001e9"};
    /**
     * Beyond the data's range: the double range's edges and halfway cases there, and the doubles just above
     * VALUE_MAX. Drawn less often than HARD: any one of them rejects the whole file.
     */
    private static final String[] BEYOND = {"1.7976931348623157e308", "1.7976931348623158e308", "1.7976931348623159e308",
        "9007199254740993", "9007199254740992.5", "1e400", "1e23", "8.41e21", "7.2057594037927933e16",
        "1000000000.0000001", "-1.0000000000000002e9"};
    /** The bytes mutations insert: what separates, ends, signs or breaks a number. */
    private static final byte[] SPECIAL = {0, '\r', '\n', '\t', ' ', 0x0b, 0x0c, '#', '!', '+', '-', '.', 'e', 'E',
        'x', 'd', 'f', 'n', 'a', 'i', '0', '9', '=', ',', ';', (byte) 0xef, (byte) 0xbb, (byte) 0xbf, (byte) 0xa0,
        (byte) 0xff, 0x7f, '\\', 'u'};

    private final Random random;

    DataMutator(long seed) {
        random = new Random(seed);
    }

    /** A number in one of the grammar's spellings, or a hard one. */
    String number(double magnitude) {
        double v = random.nextDouble() * magnitude * (random.nextInt(8) == 0 ? -1 : 1);
        switch (random.nextInt(9)) {
            case 0:
                return random.nextInt(8) == 0 ? BEYOND[random.nextInt(BEYOND.length)] : HARD[random.nextInt(HARD.length)];
            case 1:
                return String.format(Locale.ROOT, "%.3f", v);
            case 2:
                return Long.toString((long) (v * 1000));
            case 3: {
                // long mantissas: now and then as they are (beyond VALUE_MAX, or the double range, past 9 digits),
                // else scaled into the data's range, down to subnormals and underflow
                int n = 1 + random.nextInt(400);
                String mantissa = digits(n) + "." + digits(random.nextInt(60));
                switch (random.nextInt(16)) {
                    case 0:
                        return mantissa;
                    case 1:
                        return mantissa + "e-" + (n - 1 + random.nextInt(400));
                    default:
                        return mantissa + "e" + (random.nextInt(22) - 14 - (n - 1));
                }
            }
            case 4:
                return Double.toString(v).toUpperCase(Locale.ROOT);
            default:
                return String.format(Locale.ROOT, "%.16e", v);
        }
    }

    /**
     * A laser's angle: in [0, 2pi) in one of the grammar's spellings, now and then any number (which the
     * reader refuses when it is outside), so that a laser file of several lines is still accepted often.
     */
    private String angle() {
        if (random.nextInt(12) == 0) {
            return number(10);
        }
        double a = random.nextDouble() * 6.283185307179586;
        switch (random.nextInt(3)) {
            case 0:
                return String.format(Locale.ROOT, "%.3f", a);
            case 1:
                return Double.toString(a);
            default:
                return String.format(Locale.ROOT, "%.16e", a);
        }
    }

    private String digits(int n) {
        StringBuilder b = new StringBuilder(n);
        for (int i = 0; i < n; i++) {
            b.append((char) ('0' + random.nextInt(10)));
        }
        return b.toString();
    }

    private String blanks() {
        int n = random.nextInt(10) == 0 ? 0 : 1 + random.nextInt(3);
        StringBuilder b = new StringBuilder();
        for (int i = 0; i < n; i++) {
            b.append(random.nextInt(4) == 0 ? '\t' : ' ');
        }
        return b.toString();
    }

    /**
     * An event file of about {@code columns} columns (2: a laser file, whose angles are in [0, 2pi) more often than
     * not): sorted times, blank and comment lines, CRLF now and then.
     */
    byte[] eventFile(int columns) {
        StringBuilder b = new StringBuilder();
        int rows = random.nextInt(10);
        double t = 0;
        String end = random.nextInt(5) == 0 ? "\r\n" : "\n";
        for (int r = 0; r < rows; r++) {
            if (random.nextInt(8) == 0) {
                b.append(random.nextBoolean() ? blanks() : blanks() + "# comment " + r).append(end);
            }
            t += random.nextInt(4) == 0 ? 0 : random.nextDouble() * 0.1;
            int cols = random.nextInt(40) == 0 ? columns + random.nextInt(3) - 1 : columns;
            if (random.nextBoolean()) {
                b.append(blanks());
            }
            for (int c = 0; c < cols; c++) {
                b.append(c == 0 ? (random.nextInt(20) == 0 ? number(1) : String.format(Locale.ROOT, "%.16e", t))
                        : columns == 2 ? angle() : number(10));
                b.append(c + 1 < cols ? (random.nextBoolean() ? "  " : blanks().isEmpty() ? " " : blanks()) : "");
            }
            if (random.nextInt(6) == 0) {
                b.append(blanks());
            }
            if (r + 1 < rows || random.nextInt(4) != 0) {
                b.append(end);
            }
        }
        return mutate(b.toString().getBytes(StandardCharsets.ISO_8859_1));
    }

    private static final String[] KEYS = {"playground.width", "playground.height", "start.x", "start.y",
        "start.theta", "beacons", "scenario", "format", "seed", "duration", "laser.rps"};

    /** A dataset.properties: known and unknown keys, comments, Java Properties syntax the grammar lacks. */
    byte[] propertiesFile() {
        StringBuilder b = new StringBuilder();
        int lines = random.nextInt(10);
        for (int i = 0; i < lines; i++) {
            String key = KEYS[random.nextInt(KEYS.length)];
            String value;
            if (key.equals("beacons")) {
                value = beacons();
            } else if (key.equals("scenario") || key.equals("format")) {
                value = random.nextInt(10) == 0 ? digits(120 + random.nextInt(16)) : "match-" + random.nextInt(9);
            } else {
                value = number(random.nextBoolean() ? 4 : 1);
            }
            switch (random.nextInt(12)) {
                case 0:
                    b.append(random.nextBoolean() ? "# " : "! ").append(key);
                    break;
                case 1:
                    b.append(key).append(random.nextBoolean() ? ':' : ' ').append(value);
                    break;
                case 2:
                    b.append(key).append("=\\u00").append(value);
                    break;
                default:
                    b.append(blanks()).append(key).append(blanks()).append('=').append(blanks()).append(value)
                            .append(random.nextInt(5) == 0 ? blanks() : "");
            }
            b.append(random.nextInt(6) == 0 ? "\r\n" : "\n");
        }
        return mutate(b.toString().getBytes(StandardCharsets.ISO_8859_1));
    }

    private String beacons() {
        int n = random.nextInt(10) == 0 ? 30 + random.nextInt(5) : 1 + random.nextInt(5);
        StringBuilder b = new StringBuilder();
        for (int i = 0; i < n; i++) {
            if (i > 0) {
                b.append(random.nextInt(30) == 0 ? ";;" : ";");
            }
            b.append(number(3)).append(random.nextInt(3) == 0 ? " , " : ",").append(number(2));
        }
        if (random.nextInt(20) == 0) {
            b.append(random.nextBoolean() ? ";" : ",");
        }
        return b.toString();
    }

    /** Zero to three byte-level changes: a byte replaced, inserted or removed, a line doubled or swapped, a cut. */
    byte[] mutate(byte[] in) {
        byte[] out = in;
        int n = random.nextBoolean() ? 0 : 1 + random.nextInt(3);
        for (int k = 0; k < n; k++) {
            int at = out.length == 0 ? 0 : random.nextInt(out.length);
            byte s = SPECIAL[random.nextInt(SPECIAL.length)];
            switch (random.nextInt(7)) {
                case 0:
                    if (out.length > 0) {
                        out = out.clone();
                        out[at] = s;
                    }
                    break;
                case 1:
                    out = splice(out, at, 0, new byte[] {s});
                    break;
                case 2:
                    out = out.length > 0 ? splice(out, at, 1, new byte[0]) : out;
                    break;
                case 3:
                    out = splice(out, 0, 0, new byte[] {(byte) 0xef, (byte) 0xbb, (byte) 0xbf});
                    break;
                case 4:
                    out = java.util.Arrays.copyOf(out, at);
                    break;
                default:
                    out = shuffleLines(out);
            }
        }
        return out;
    }

    private byte[] shuffleLines(byte[] in) {
        List<String> lines = new ArrayList<>();
        for (String l : new String(in, StandardCharsets.ISO_8859_1).split("\n", -1)) {
            lines.add(l);
        }
        if (lines.size() < 2) {
            return in;
        }
        int i = random.nextInt(lines.size());
        int j = random.nextInt(lines.size());
        if (random.nextBoolean()) {
            lines.add(j, lines.get(i));
        } else {
            String l = lines.get(i);
            lines.set(i, lines.get(j));
            lines.set(j, l);
        }
        return String.join("\n", lines).getBytes(StandardCharsets.ISO_8859_1);
    }

    private static byte[] splice(byte[] in, int at, int remove, byte[] insert) {
        ByteArrayOutputStream b = new ByteArrayOutputStream();
        b.write(in, 0, at);
        b.write(insert, 0, insert.length);
        b.write(in, at + remove, in.length - at - remove);
        return b.toByteArray();
    }
}
