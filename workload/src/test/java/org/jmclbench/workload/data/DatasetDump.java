package org.jmclbench.workload.data;

import java.io.ByteArrayInputStream;
import java.io.File;
import java.util.Locale;

import org.jmclbench.core.mcl.Playground;
import org.jmclbench.workload.BadInputException;

/**
 * What the Java reader makes of a file, in the text native/tests/dataset_dump.c writes for
 * the C reader: "error message" or "ok" and every double as its bits in hex, then "end".
 */
final class DatasetDump {
    private DatasetDump() {
    }

    /** An event file of {@code columns} columns, read from bytes named "input": 2 a laser file, 4 odometry. */
    static String series(byte[] file, int columns) {
        StringBuilder b = new StringBuilder();
        try {
            double[][] c = DatasetReader.readColumns(new ByteArrayInputStream(file), "input", columns,
                    columns == 2 ? DatasetReader.Rule.LASER : DatasetReader.Rule.NONE);
            b.append("ok\n");
            series(b, "series", c);
        } catch (BadInputException e) {
            b.append("error ").append(e.getMessage()).append('\n');
        }
        return b.append("end\n").toString();
    }

    /** A dataset.properties, read from bytes named "input". */
    static String properties(byte[] file) {
        StringBuilder b = new StringBuilder();
        try {
            DatasetMetadata m = DatasetMetadata.read(new ByteArrayInputStream(file), "input");
            b.append("ok\n");
            metadata(b, m.playground);
            b.append("\nstart ").append(m.startKnown ? "known" : "unknown");
            if (m.startKnown) {
                bits(b, m.startX);
                bits(b, m.startY);
                bits(b, m.startTheta);
            }
            b.append("\nscenario ").append(m.properties.getProperty("scenario", "")).append('\n');
        } catch (BadInputException e) {
            b.append("error ").append(e.getMessage()).append('\n');
        }
        return b.append("end\n").toString();
    }

    /** A dataset folder, or the three files when {@code files} has three paths. */
    static String dataset(String... files) {
        StringBuilder b = new StringBuilder();
        try {
            Dataset d = files.length == 1 ? DatasetReader.readFolder(new File(files[0]))
                    : DatasetReader.readFiles(new File(files[0]), new File(files[1]), new File(files[2]));
            b.append("ok\n");
            series(b, "odometry", new double[][] {d.odoTime, d.odoDx, d.odoDy, d.odoDtheta});
            series(b, "laser", new double[][] {d.laserTime, d.laserAngle});
            series(b, "real", new double[][] {d.realTime, d.realX, d.realY, d.realTheta});
            metadata(b, d.playground);
            b.append("\nscenario ").append(d.metadata.getProperty("scenario", "")).append("\nstart");
            bits(b, d.startX);
            bits(b, d.startY);
            bits(b, d.startTheta);
            b.append("\nname ").append(d.name).append('\n');
        } catch (BadInputException e) {
            b.append("error ").append(e.getMessage()).append('\n');
        }
        return b.append("end\n").toString();
    }

    private static void series(StringBuilder b, String label, double[][] columns) {
        int n = columns[0].length;
        b.append(label).append(' ').append(n).append('\n');
        for (int i = 0; i < n; i++) {
            for (double[] column : columns) {
                bits(b, column[i]);
            }
            b.append('\n');
        }
    }

    private static void metadata(StringBuilder b, Playground p) {
        b.append("playground");
        bits(b, p.width);
        bits(b, p.height);
        b.append("\nbeacons ").append(p.beaconCount());
        for (int i = 0; i < p.beaconCount(); i++) {
            bits(b, p.beaconX[i]);
            bits(b, p.beaconY[i]);
        }
    }

    private static void bits(StringBuilder b, double v) {
        b.append(String.format(Locale.ROOT, " %016x", Double.doubleToRawLongBits(v)));
    }
}
