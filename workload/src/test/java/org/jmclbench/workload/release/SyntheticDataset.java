package org.jmclbench.workload.release;

import java.io.File;
import java.io.IOException;
import java.io.PrintWriter;
import java.nio.charset.StandardCharsets;
import java.util.Locale;
import org.jmclbench.workload.BadInputException;
import org.jmclbench.workload.data.Dataset;
import org.jmclbench.workload.data.DatasetReader;

/**
 * A small thesis-format dataset written for tests: the robot drives straight along y = 0.5 from
 * x = 0.5 at 0.2 m/s, odometry every 50 ms, and the laser sees the beacons at their true bearing
 * as the turret turns at 3 rps (the thesis playground's beacons).
 */
final class SyntheticDataset {
    static final double[][] BEACONS = {{0, 1}, {3, 0}, {3, 2}};

    final File odo;
    final File laser;
    final File real;

    private SyntheticDataset(File dir) {
        odo = new File(dir, "odometry.txt");
        laser = new File(dir, "laser.txt");
        real = new File(dir, "real.txt");
    }

    /** Writes {@code seconds} of data into dir. */
    static SyntheticDataset write(File dir, double seconds) throws IOException {
        SyntheticDataset d = new SyntheticDataset(dir);
        double v = 0.2;
        try (PrintWriter o = new PrintWriter(d.odo, StandardCharsets.UTF_8.name());
             PrintWriter r = new PrintWriter(d.real, StandardCharsets.UTF_8.name())) {
            for (int i = 0; i * 0.05 <= seconds; i++) {
                double t = i * 0.05;
                line(o, t, i == 0 ? 0 : v * 0.05, 0, 0);
                line(r, t, 0.5 + v * t, 0.5, 0);
            }
        }
        try (PrintWriter l = new PrintWriter(d.laser, StandardCharsets.UTF_8.name())) {
            // the turret's angle is 2pi * 3 * t; a beacon is hit when it equals its bearing
            double turn = 1.0 / 3.0;
            for (int rev = 0; rev * turn <= seconds; rev++) {
                double[] hits = new double[BEACONS.length];
                double[] angles = new double[BEACONS.length];
                for (int b = 0; b < BEACONS.length; b++) {
                    double t0 = rev * turn;
                    double x = 0.5 + 0.2 * t0;
                    double bearing = Math.atan2(BEACONS[b][1] - 0.5, BEACONS[b][0] - x);
                    bearing = bearing < 0 ? bearing + 2 * Math.PI : bearing;
                    angles[b] = bearing;
                    hits[b] = t0 + bearing / (2 * Math.PI) * turn;
                }
                Integer[] order = {0, 1, 2};
                java.util.Arrays.sort(order, (a, b) -> Double.compare(hits[a], hits[b]));
                for (int b : order) {
                    if (hits[b] <= seconds) {
                        line(l, hits[b], angles[b]);
                    }
                }
            }
        }
        return d;
    }

    Dataset read() throws BadInputException {
        return DatasetReader.readFiles(odo, laser, real);
    }

    private static void line(PrintWriter w, double... values) {
        StringBuilder b = new StringBuilder();
        for (int i = 0; i < values.length; i++) {
            b.append(i == 0 ? "" : "  ").append(String.format(Locale.ROOT, "%.16e", values[i]));
        }
        w.print(b.append('\n'));
    }
}
