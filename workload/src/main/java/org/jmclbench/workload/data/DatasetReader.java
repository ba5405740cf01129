package org.jmclbench.workload.data;

import java.io.BufferedReader;
import java.io.File;
import java.io.FileInputStream;
import java.io.IOException;
import java.io.InputStreamReader;
import java.io.Reader;
import java.nio.charset.StandardCharsets;
import java.util.Properties;
import java.util.regex.Pattern;

import org.jmclbench.workload.BadInputException;
import org.jmclbench.core.mcl.Playground;

/**
 * Reads a dataset folder or the thesis's three bare files (docs/FORMATS.md section 1),
 * rejecting anything malformed with a one-line {@code file:line: problem} message.
 */
public final class DatasetReader {
    public static final String ODOMETRY = "odometry.txt";
    public static final String LASER = "laser.txt";
    public static final String REAL = "real.txt";
    public static final String METADATA = "dataset.properties";

    private DatasetReader() {
    }

    /** Reads {@code odometry.txt}, {@code laser.txt}, {@code real.txt} and the optional {@code dataset.properties}. */
    public static Dataset readFolder(File dir) throws BadInputException {
        if (!dir.isDirectory()) {
            throw new BadInputException(dir.getPath() + ": no such dataset folder");
        }
        Properties meta = new Properties();
        File metaFile = new File(dir, METADATA);
        if (metaFile.isFile()) {
            try (Reader r = new InputStreamReader(new FileInputStream(metaFile), StandardCharsets.UTF_8)) {
                meta.load(r);
            } catch (IOException | IllegalArgumentException e) {
                throw new BadInputException(metaFile.getPath() + ": cannot read: " + e.getMessage());
            }
        }
        return read(new File(dir, ODOMETRY), new File(dir, LASER), new File(dir, REAL), meta, metaFile, dir);
    }

    /** Reads the thesis's three files (no metadata: the thesis's playground, the first real pose as start). */
    public static Dataset readFiles(File odo, File laser, File real) throws BadInputException {
        return read(odo, laser, real, new Properties(), null, null);
    }

    private static Dataset read(File odoFile, File laserFile, File realFile, Properties meta, File metaFile,
            File folder) throws BadInputException {
        double[][] odo = readColumns(odoFile, 4);
        double[][] laser = readColumns(laserFile, 2);
        double[][] real = readColumns(realFile, 4);
        String metaName = metaFile == null ? "" : metaFile.getPath();
        Playground playground = playground(meta, metaName);
        double sx;
        double sy;
        double st;
        if (meta.getProperty("start.x") != null || meta.getProperty("start.y") != null
                || meta.getProperty("start.theta") != null) {
            sx = number(meta, "start.x", metaName);
            sy = number(meta, "start.y", metaName);
            st = number(meta, "start.theta", metaName);
        } else {
            sx = real[1][0];
            sy = real[2][0];
            st = real[3][0];
        }
        String name = meta.getProperty("scenario");
        if (name == null || name.isEmpty()) {
            name = folder != null ? folder.getName() : odoFile.getName();
        }
        return new Dataset(odo, laser, real, playground, sx, sy, st, meta, name, folder, odoFile, laserFile,
                realFile);
    }

    private static Playground playground(Properties meta, String metaName) throws BadInputException {
        Playground thesis = Playground.thesis();
        double w = meta.getProperty("playground.width") == null ? thesis.width
                : number(meta, "playground.width", metaName);
        double h = meta.getProperty("playground.height") == null ? thesis.height
                : number(meta, "playground.height", metaName);
        double[] bx = thesis.beaconX;
        double[] by = thesis.beaconY;
        String beacons = meta.getProperty("beacons");
        if (beacons != null) {
            String[] pairs = beacons.trim().split(";");
            bx = new double[pairs.length];
            by = new double[pairs.length];
            for (int i = 0; i < pairs.length; i++) {
                String[] xy = pairs[i].trim().split(",");
                if (xy.length != 2) {
                    throw new BadInputException(metaName + ": beacons: expected x,y;x,y;... but got '" + beacons + "'");
                }
                bx[i] = parseFinite(xy[0].trim(), metaName + ": beacons");
                by[i] = parseFinite(xy[1].trim(), metaName + ": beacons");
            }
        }
        if (!(w > 0) || !(h > 0)) {
            throw new BadInputException(metaName + ": playground size must be positive");
        }
        return new Playground(w, h, bx, by);
    }

    private static double number(Properties meta, String key, String metaName) throws BadInputException {
        String v = meta.getProperty(key);
        if (v == null) {
            throw new BadInputException(metaName + ": " + key + ": missing");
        }
        return parseFinite(v.trim(), metaName + ": " + key);
    }

    private static double parseFinite(String token, String where) throws BadInputException {
        double v;
        try {
            v = Double.parseDouble(token);
        } catch (NumberFormatException e) {
            throw new BadInputException(where + ": not a number: '" + token + "'");
        }
        if (Double.isNaN(v) || Double.isInfinite(v)) {
            throw new BadInputException(where + ": not a finite number: '" + token + "'");
        }
        return v;
    }

    /** A plain decimal number (what %.16e and C's strtod agree on): no hex, no 'd'/'f' suffix, no NaN or infinity. */
    private static final Pattern DECIMAL = Pattern.compile("[+-]?(\\d+\\.?\\d*|\\.\\d+)([eE][+-]?\\d+)?");

    private static double number(String token, String file, int line) throws BadInputException {
        if (!DECIMAL.matcher(token).matches()) {
            String t = token.toLowerCase(java.util.Locale.ROOT).replace("+", "").replace("-", "");
            if (t.equals("nan") || t.equals("inf") || t.equals("infinity")) {
                throw BadInputException.atLine(file, line, "not a finite number: '" + token + "'");
            }
            throw BadInputException.atLine(file, line, "not a number: '" + token + "'");
        }
        double v = Double.parseDouble(token);
        if (Double.isInfinite(v)) {
            throw BadInputException.atLine(file, line, "not a finite number: '" + token + "' (overflows)");
        }
        return v;
    }

    /**
     * Reads a whitespace-separated numeric file with exactly {@code columns} numbers a line;
     * column 0 is a time, non-negative and non-decreasing. Returns the columns.
     */
    static double[][] readColumns(File file, int columns) throws BadInputException {
        String name = file.getPath();
        if (!file.isFile()) {
            throw new BadInputException(name + ": no such file");
        }
        double[][] out = new double[columns][256];
        int count = 0;
        try (BufferedReader r = new BufferedReader(
                new InputStreamReader(new FileInputStream(file), StandardCharsets.UTF_8))) {
            String line;
            int lineNo = 0;
            double previous = 0.0;
            while ((line = r.readLine()) != null) {
                lineNo++;
                String s = line.trim();
                if (s.isEmpty() || s.charAt(0) == '#') {
                    continue;
                }
                String[] tokens = s.split("\\s+");
                if (tokens.length != columns) {
                    throw BadInputException.atLine(name, lineNo,
                            "expected " + columns + " columns but found " + tokens.length);
                }
                if (count == out[0].length) {
                    for (int c = 0; c < columns; c++) {
                        out[c] = java.util.Arrays.copyOf(out[c], count * 2);
                    }
                }
                for (int c = 0; c < columns; c++) {
                    out[c][count] = number(tokens[c], name, lineNo);
                }
                double t = out[0][count];
                if (t < 0) {
                    throw BadInputException.atLine(name, lineNo, "negative time " + tokens[0]);
                }
                if (count > 0 && t < previous) {
                    throw BadInputException.atLine(name, lineNo,
                            "time " + tokens[0] + " is before the previous line's (not sorted by time)");
                }
                previous = t;
                count++;
            }
        } catch (IOException e) {
            throw new BadInputException(name + ": cannot read: " + e.getMessage());
        }
        if (count == 0) {
            throw new BadInputException(name + ": empty file (no data lines)");
        }
        for (int c = 0; c < columns; c++) {
            out[c] = java.util.Arrays.copyOf(out[c], count);
        }
        return out;
    }
}
