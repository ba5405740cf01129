package org.jmclbench.workload.data;

import java.io.BufferedInputStream;
import java.io.File;
import java.io.IOException;
import java.io.InputStream;
import java.util.Arrays;

import org.jmclbench.core.mcl.Angles;
import org.jmclbench.workload.BadInputException;

/**
 * Reads a dataset folder or the thesis's three bare files (docs/FORMATS.md section 1),
 * rejecting anything malformed with a one-line {@code file:line: problem} message. The grammar
 * is native/src/dataset.c's too, byte for byte: both readers accept the same files, read the
 * same doubles and name the same line (DatasetDifferentialTest).
 */
public final class DatasetReader {
    public static final String ODOMETRY = "odometry.txt";
    public static final String LASER = "laser.txt";
    public static final String REAL = "real.txt";
    public static final String METADATA = "dataset.properties";

    private DatasetReader() {
    }

    /**
     * Reads {@code odometry.txt}, {@code laser.txt}, {@code real.txt} and the optional
     * {@code dataset.properties}, in this order (the C reader's too, so that a folder with two
     * problems is named by the same one).
     */
    public static Dataset readFolder(File dir) throws BadInputException {
        if (!dir.isDirectory()) {
            throw new BadInputException(dir.getPath() + ": no such dataset folder");
        }
        File odo = new File(dir, ODOMETRY);
        File laser = new File(dir, LASER);
        File real = new File(dir, REAL);
        double[][] o = readColumns(odo, 4, Rule.NONE);
        double[][] l = readColumns(laser, 2, Rule.LASER);
        double[][] r = readColumns(real, 4, Rule.atTimesOf(o[0], odo.getPath()));
        File metaFile = new File(dir, METADATA);
        DatasetMetadata meta = DatasetMetadata.none();
        InputStream in = DataGrammar.open(metaFile, true);
        if (in != null) {
            try (InputStream stream = in) {
                meta = DatasetMetadata.read(new BufferedInputStream(stream), metaFile.getPath());
            } catch (IOException e) {
                throw new BadInputException(metaFile.getPath() + ": cannot read");
            }
        }
        return dataset(o, l, r, meta, dir, odo, laser, real);
    }

    /** Reads the thesis's three files (no metadata: the thesis's playground, the first real pose as start). */
    public static Dataset readFiles(File odo, File laser, File real) throws BadInputException {
        double[][] o = readColumns(odo, 4, Rule.NONE);
        double[][] l = readColumns(laser, 2, Rule.LASER);
        double[][] r = readColumns(real, 4, Rule.atTimesOf(o[0], odo.getPath()));
        return dataset(o, l, r, DatasetMetadata.none(), null, odo, laser, real);
    }

    private static Dataset dataset(double[][] odo, double[][] laser, double[][] real, DatasetMetadata meta,
            File folder, File odoFile, File laserFile, File realFile) {
        double sx = meta.startKnown ? meta.startX : real[1][0];
        double sy = meta.startKnown ? meta.startY : real[2][0];
        double st = meta.startKnown ? meta.startTheta : real[3][0];
        String name = meta.properties.getProperty("scenario");
        if (name == null || name.isEmpty()) {
            name = folder != null ? folder.getName() : odoFile.getName();
        }
        return new Dataset(odo, laser, real, meta.playground, sx, sy, st, meta.properties, name, folder, odoFile,
                laserFile, realFile);
    }

    /**
     * What the records of one event file must satisfy beyond the grammar (docs/FORMATS.md 1.1):
     * a column that is an angle in [0, 2pi) (the laser's), and the times of another file's
     * records, one record each (the ground truth is at the odometry times). The C reader's jm_rule.
     */
    public static final class Rule {
        /** No more than the grammar: the odometry. */
        public static final Rule NONE = new Rule(-1, null, null);
        /** The laser's: column 1 is the beacon's angle from the heading, in [0, 2pi) (SPEC section 1). */
        public static final Rule LASER = new Rule(1, null, null);

        final int angleColumn;
        final double[] times;
        final String timesName;

        private Rule(int angleColumn, double[] times, String timesName) {
            this.angleColumn = angleColumn;
            this.times = times;
            this.timesName = timesName;
        }

        /**
         * The ground truth's: record i at the time of record i of {@code times} (read from the file
         * {@code name}), as many records as it has; the deviation is the mean over the odometry
         * times (docs/ALGORITHM.md 10), which another time or count would silently change.
         */
        public static Rule atTimesOf(double[] times, String name) {
            return new Rule(-1, times, name);
        }
    }

    /**
     * Reads a whitespace-separated numeric file with exactly {@code columns} numbers a line;
     * column 0 is a time, non-negative and non-decreasing; each record as {@code rule} says.
     * Returns the columns.
     */
    static double[][] readColumns(File file, int columns, Rule rule) throws BadInputException {
        String name = file.getPath();
        try (InputStream in = DataGrammar.open(file, false)) {
            return readColumns(in, name, columns, rule);
        } catch (IOException e) {
            throw new BadInputException(name + ": cannot read");
        }
    }

    /**
     * The same from a stream (docs/FORMATS.md 1.1), {@code name} being what messages call it:
     * {@code columns} arrays of the rows' values.
     */
    public static double[][] readColumns(InputStream in, String name, int columns, Rule rule)
            throws BadInputException {
        double[][] out = new double[columns][256];
        int[] start = new int[columns];
        int[] length = new int[columns];
        double[] value = new double[1];
        int count = 0;
        DataGrammar.Lines lines = new DataGrammar.Lines(in);
        int lineNo = 0;
        double previous = 0.0;
        try {
            while (lines.next()) {
                lineNo++;
                byte[] b = lines.line;
                int n = lines.length;
                int first = 0;
                while (first < n && DataGrammar.isBlank(b[first])) {
                    first++;
                }
                if (first == n || b[first] == '#') {
                    continue; // blank line or comment
                }
                int tokens = split(b, n, start, length);
                if (tokens != columns) {
                    throw BadInputException.atLine(name, lineNo,
                            "expected " + columns + " columns but found " + tokens);
                }
                if (count == out[0].length) {
                    for (int c = 0; c < columns; c++) {
                        out[c] = Arrays.copyOf(out[c], count * 2);
                    }
                }
                for (int c = 0; c < columns; c++) {
                    int r = DataGrammar.parseNumber(b, start[c], length[c], value);
                    if (r != DataGrammar.NUM_OK) {
                        throw BadInputException.atLine(name, lineNo,
                                DataGrammar.numberProblem(r, b, start[c], length[c]));
                    }
                    out[c][count] = value[0];
                }
                double t = out[0][count];
                if (t < 0 || (count > 0 && t < previous)) {
                    String time = DataGrammar.quote(b, start[0], length[0]);
                    throw BadInputException.atLine(name, lineNo, t < 0 ? "negative time " + time
                            : "time " + time + " is before the previous line's (not sorted by time)");
                }
                checkRule(rule, out, count, b, start, length, name, lineNo);
                previous = t;
                count++;
            }
        } catch (IOException e) {
            throw new BadInputException(name + ": cannot read");
        }
        if (count == 0) {
            throw new BadInputException(name + ": empty file (no data lines)");
        }
        if (rule.times != null && count < rule.times.length) {
            throw new BadInputException(name + ": " + count + " records for the " + rule.times.length + " of "
                    + rule.timesName + " (the ground truth is at the odometry times)");
        }
        for (int c = 0; c < columns; c++) {
            out[c] = Arrays.copyOf(out[c], count);
        }
        return out;
    }

    /** Refuses record {@code row} (at line {@code lineNo}) when it breaks {@code rule}. */
    private static void checkRule(Rule rule, double[][] out, int row, byte[] b, int[] start, int[] length, String name,
            int lineNo) throws BadInputException {
        int a = rule.angleColumn;
        if (a >= 0 && !(out[a][row] >= 0 && out[a][row] < Angles.TWO_PI)) {
            throw BadInputException.atLine(name, lineNo, "angle " + DataGrammar.quote(b, start[a], length[a])
                    + " is not in [0, 2pi) (the beacon's angle from the heading)");
        }
        if (rule.times == null) {
            return;
        }
        String time = DataGrammar.quote(b, start[0], length[0]);
        if (row >= rule.times.length) {
            throw BadInputException.atLine(name, lineNo, "time " + time + " after the last of the " + rule.times.length
                    + " records of " + rule.timesName + " (the ground truth is at the odometry times)");
        }
        if (out[0][row] != rule.times[row]) {
            throw BadInputException.atLine(name, lineNo, "time " + time + " is not that of record " + (row + 1) + " of "
                    + rule.timesName + " (the ground truth is at the odometry times)");
        }
    }

    /** The blank-separated tokens of {@code b[0..n)}: the first starts and lengths, and their count. */
    private static int split(byte[] b, int n, int[] start, int[] length) {
        int tokens = 0;
        int i = 0;
        for (;;) {
            while (i < n && DataGrammar.isBlank(b[i])) {
                i++;
            }
            if (i == n) {
                return tokens;
            }
            int from = i;
            while (i < n && !DataGrammar.isBlank(b[i])) {
                i++;
            }
            if (tokens < start.length) {
                start[tokens] = from;
                length[tokens] = i - from;
            }
            tokens++;
        }
    }
}
