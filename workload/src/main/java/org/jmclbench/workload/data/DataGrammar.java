package org.jmclbench.workload.data;

import java.io.File;
import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.AccessDeniedException;
import java.nio.file.Files;
import java.nio.file.InvalidPathException;
import java.nio.file.Path;
import java.nio.file.attribute.BasicFileAttributes;
import java.util.Arrays;

import org.jmclbench.workload.BadInputException;

/**
 * The byte-level grammar of the data files (docs/FORMATS.md 1.1): lines, blanks, numbers and
 * how a message quotes what it read. The C reader (native/src/dataset.c) implements the same
 * grammar and says the same words; keep the two in step (DatasetDifferentialTest holds them).
 */
final class DataGrammar {
    /** The most bytes of a token or value a message quotes. */
    static final int QUOTE_MAX = 40;

    /** parseNumber's answers. */
    static final int NUM_OK = 0;
    static final int NUM_SYNTAX = 1;
    static final int NUM_NON_FINITE = 2;
    static final int NUM_OVERFLOW = 3;
    static final int NUM_OUT_OF_RANGE = 4;

    /**
     * The largest magnitude of a data value (docs/FORMATS.md 1.1): 1e9 s of time is 1e18 ns, well
     * inside a 64-bit release time with room for the clock's origin and the deadlines; 1e9 m or rad
     * is far beyond any robot's, and keeps the filter's sums and squares finite (a 1e308 increment
     * made every later estimate NaN).
     */
    public static final double VALUE_MAX = 1e9;
    /** VALUE_MAX as the messages write it (the C reader's words too). */
    static final String VALUE_MAX_TEXT = "1e9";

    private DataGrammar() {
    }

    /** What separates numbers on a line: space and tab, nothing else. */
    static boolean isBlank(int c) {
        return c == ' ' || c == '\t';
    }

    private static boolean isDigit(int c) {
        return c >= '0' && c <= '9';
    }

    /** Reads a stream line by line as bytes: LF ends a line, a CR right before it (or the end) is dropped. */
    static final class Lines {
        private final InputStream in;
        private final byte[] chunk = new byte[1 << 16];
        private int pos;
        private int end;
        /** The current line: {@code line[0..length)}. */
        byte[] line = new byte[256];
        int length;

        Lines(InputStream in) {
            this.in = in;
        }

        /** Advances to the next line; false at the end of the stream. */
        boolean next() throws IOException {
            length = 0;
            boolean any = false;
            for (;;) {
                if (pos == end) {
                    end = in.read(chunk, 0, chunk.length);
                    pos = 0;
                    if (end <= 0) {
                        end = 0;
                        break;
                    }
                }
                any = true;
                byte b = chunk[pos++];
                if (b == '\n') {
                    break;
                }
                if (length == line.length) {
                    line = Arrays.copyOf(line, line.length * 2);
                }
                line[length++] = b;
            }
            if (length > 0 && line[length - 1] == '\r') {
                length--;
            }
            return any;
        }
    }

    /** Whether {@code b[off..off+len)} is {@code [+-]?(digits[.[digits]] | .digits)[(e|E)[+-]digits]}. */
    static boolean plainDecimal(byte[] b, int off, int len) {
        int p = off;
        int end = off + len;
        int digits = 0;
        if (p < end && (b[p] == '+' || b[p] == '-')) {
            p++;
        }
        for (; p < end && isDigit(b[p]); p++) {
            digits++;
        }
        if (p < end && b[p] == '.') {
            for (p++; p < end && isDigit(b[p]); p++) {
                digits++;
            }
        }
        if (digits == 0) {
            return false;
        }
        if (p < end && (b[p] == 'e' || b[p] == 'E')) {
            p++;
            if (p < end && (b[p] == '+' || b[p] == '-')) {
                p++;
            }
            if (p == end || !isDigit(b[p])) {
                return false;
            }
            while (p < end && isDigit(b[p])) {
                p++;
            }
        }
        return p == end;
    }

    /** NaN or infinity in any case, signs anywhere: "not a finite number" rather than "not a number". */
    static boolean namesNonFinite(byte[] b, int off, int len) {
        StringBuilder t = new StringBuilder(9);
        for (int i = off; i < off + len; i++) {
            int c = b[i];
            if (c == '+' || c == '-') {
                continue;
            }
            if (t.length() == 9) {
                return false;
            }
            t.append((char) (c >= 'A' && c <= 'Z' ? c - 'A' + 'a' : c & 0xff));
        }
        String s = t.toString();
        return s.equals("nan") || s.equals("inf") || s.equals("infinity");
    }

    /**
     * Parses {@code b[off..off+len)} as a double of magnitude at most VALUE_MAX into {@code out[0]}: the value correctly
     * rounded, as C's strtod gives it, since the grammar leaves no syntax on which they differ.
     */
    static int parseNumber(byte[] b, int off, int len, double[] out) {
        if (!plainDecimal(b, off, len)) {
            return namesNonFinite(b, off, len) ? NUM_NON_FINITE : NUM_SYNTAX;
        }
        double v = Double.parseDouble(new String(b, off, len, StandardCharsets.ISO_8859_1));
        if (Double.isInfinite(v)) {
            return NUM_OVERFLOW;
        }
        if (Math.abs(v) > VALUE_MAX) {
            return NUM_OUT_OF_RANGE;
        }
        out[0] = v;
        return NUM_OK;
    }

    /** The words of a number's problem with the quoted token, as both readers write it. */
    static String numberProblem(int r, byte[] b, int off, int len) {
        return (r == NUM_SYNTAX ? "not a number" : r == NUM_OUT_OF_RANGE ? "out of range" : "not a finite number")
                + ": '" + quote(b, off, len) + "'" + (r == NUM_OVERFLOW ? " (overflows)"
                : r == NUM_OUT_OF_RANGE ? " (more than " + VALUE_MAX_TEXT + " in magnitude)" : "");
    }

    /**
     * A token or value as a message quotes it: printable ASCII as is, every other byte (and the
     * backslash) as \xHH, at most {@link #QUOTE_MAX} bytes and then "...": one printable line.
     */
    static String quote(byte[] b, int off, int len) {
        StringBuilder s = new StringBuilder();
        int n = Math.min(len, QUOTE_MAX);
        for (int i = off; i < off + n; i++) {
            int c = b[i] & 0xff;
            if (c >= 0x20 && c < 0x7f && c != '\\') {
                s.append((char) c);
            } else {
                s.append("\\x").append(hex(c));
            }
        }
        if (len > QUOTE_MAX) {
            s.append("...");
        }
        return s.toString();
    }

    /** A byte as two lower-case hex digits. */
    static String hex(int c) {
        return new String(new char[] {Character.forDigit((c >> 4) & 15, 16), Character.forDigit(c & 15, 16)});
    }

    /**
     * Opens a file of a dataset, or says why not in the words both readers use: "no such file"
     * (nothing there, whatever the reason), "is a directory", "not a regular file" (a FIFO would
     * block the run), "permission denied", "cannot read". Returns null when the file is optional
     * and nothing is there.
     */
    static InputStream open(File file, boolean optional) throws BadInputException {
        String name = file.getPath();
        Path path;
        BasicFileAttributes a;
        try {
            path = file.toPath();
            a = Files.readAttributes(path, BasicFileAttributes.class);
        } catch (AccessDeniedException e) {
            throw new BadInputException(name + ": permission denied");
        } catch (IOException | InvalidPathException e) {
            if (optional) {
                return null;
            }
            throw new BadInputException(name + ": no such file");
        }
        if (a.isDirectory()) {
            throw new BadInputException(name + ": is a directory");
        }
        if (!a.isRegularFile()) {
            throw new BadInputException(name + ": not a regular file");
        }
        try {
            return Files.newInputStream(path);
        } catch (AccessDeniedException e) {
            throw new BadInputException(name + ": permission denied");
        } catch (IOException e) {
            throw new BadInputException(name + ": cannot read");
        }
    }
}
