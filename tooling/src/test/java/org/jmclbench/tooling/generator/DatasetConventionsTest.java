package org.jmclbench.tooling.generator;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import org.jmclbench.core.mcl.Angles;
import org.jmclbench.tooling.Fixtures;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * The shipped datasets and the independent one (scripts/independent_dataset.py, which shares
 * no code with the generator) follow the same conventions: odometry increments in the
 * previous pose's frame chain up to the ground truth, and every laser angle is a beacon's
 * bearing relative to the heading, counter-clockwise, seen from the true pose.
 */
class DatasetConventionsTest {
    private static final double[][] BEACONS = {{0, 1}, {3, 0}, {3, 2}};

    static Path folder(String name) {
        Path home = Fixtures.projectHome();
        return name.equals("independent") ? home.resolve("tooling/src/test/resources/independent")
                : home.resolve("data").resolve(name);
    }

    /** Reads a whitespace-separated table as a thesis-format reader would. */
    static double[][] read(Path file) throws IOException {
        List<double[]> rows = new ArrayList<>();
        for (String l : Files.readAllLines(file)) {
            String[] tokens = l.trim().split("\\s+");
            double[] row = new double[tokens.length];
            for (int i = 0; i < tokens.length; i++) {
                row[i] = Double.parseDouble(tokens[i]);
            }
            rows.add(row);
        }
        return rows.toArray(new double[0][]);
    }

    @ParameterizedTest
    @ValueSource(strings = {"independent", "match", "figure8", "stay"})
    void laserAnglesAreBeaconBearingsFromTheTruePose(String name) throws IOException {
        double[][] real = read(folder(name).resolve("real.txt"));
        double[][] laser = read(folder(name).resolve("laser.txt"));
        double sumSq = 0;
        for (double[] l : laser) {
            // The pose at the laser time, linear between the real.txt lines around it.
            int i = 0;
            while (i < real.length - 1 && real[i + 1][0] < l[0]) {
                i++;
            }
            double[] a = real[i];
            double[] b = real[Math.min(i + 1, real.length - 1)];
            double f = b[0] == a[0] ? 0 : Math.max(0, Math.min(1, (l[0] - a[0]) / (b[0] - a[0])));
            double x = a[1] + f * (b[1] - a[1]);
            double y = a[2] + f * (b[2] - a[2]);
            double th = a[3] + f * Angles.wrapPi(b[3] - a[3]);
            double best = Double.POSITIVE_INFINITY;
            for (double[] beacon : BEACONS) {
                best = Math.min(best, Math.abs(Angles.wrapPi(l[1] - Angles.bearing(x, y, th, beacon[0], beacon[1]))));
            }
            assertTrue(best < 0.08, name + " t=" + l[0] + ": " + best + " rad from every beacon");
            sumSq += best * best;
        }
        double rms = Math.sqrt(sumSq / laser.length);
        assertTrue(rms > 0.005 && rms < 0.02, name + ": laser residual rms " + rms + " rad (noise 0.01)");
        // Three beacons, three turns a second, a few missed.
        double rate = laser.length / real[real.length - 1][0];
        assertTrue(rate > 8.0 && rate < 9.5, name + ": " + rate + " detections a second");
    }

    @ParameterizedTest
    @ValueSource(strings = {"independent", "match", "figure8"})
    void odometryChainsUpToTheGroundTruth(String name) throws IOException {
        double[][] odometry = read(folder(name).resolve("odometry.txt"));
        double[][] real = read(folder(name).resolve("real.txt"));
        assertEquals(odometry.length, real.length);
        // Start from the first real line, as the MCL does for bare thesis-format files.
        double x = real[0][1];
        double y = real[0][2];
        double th = real[0][3];
        double worst = 0;
        for (int i = 1; i < odometry.length; i++) {
            double[] o = odometry[i];
            x += o[1] * Math.cos(th) - o[2] * Math.sin(th);
            y += o[1] * Math.sin(th) + o[2] * Math.cos(th);
            th += o[3];
            worst = Math.max(worst, Math.hypot(x - real[i][1], y - real[i][2]));
            // Re-anchor every 10 s: dead reckoning drifts, the convention must hold locally.
            if (i % 200 == 0) {
                x = real[i][1];
                y = real[i][2];
                th = real[i][3];
            }
        }
        assertTrue(worst < 0.15, name + ": dead reckoning " + worst + " m off the ground truth within 10 s");
    }
}
