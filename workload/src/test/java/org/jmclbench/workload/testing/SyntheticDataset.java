package org.jmclbench.workload.testing;

import java.io.File;
import java.io.IOException;
import java.io.PrintWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.util.List;
import java.util.Locale;

import org.jmclbench.core.mcl.Angles;
import org.jmclbench.core.mcl.Playground;
import org.jmclbench.core.mcl.Rng;

/**
 * A small robot simulation for tests (the real generator lives in the tooling): the robot
 * drives a circle (or stands still) on the thesis's playground; odometry every 50 ms with a
 * little noise, a laser turret at 3 rps reporting beacon crossings with 0.01 rad noise.
 */
public final class SyntheticDataset {
    public static final double START_X = 1.5;
    public static final double START_Y = 0.4;
    public static final double START_THETA = 0.0;

    private SyntheticDataset() {
    }

    /**
     * Moves the odometry event {@code row} (0 = the first data line) of the dataset in {@code dir}
     * {@code seconds} later, so the odometry is no longer periodic, and its ground truth with it; returns its
     * line number in the file.
     */
    public static int delayOdometryEvent(File dir, int row, double seconds) throws IOException {
        delayRow(new File(dir, "real.txt"), row, seconds); // the ground truth is at the odometry times
        return delayRow(new File(dir, "odometry.txt"), row, seconds);
    }

    /** Adds {@code seconds} to the time of record {@code row} (from 0) of an event file; returns its line number. */
    private static int delayRow(File file, int row, double seconds) throws IOException {
        List<String> lines = Files.readAllLines(file.toPath(), StandardCharsets.UTF_8);
        int line = 0;
        for (int i = 0, rows = -1; i < lines.size(); i++) {
            if (!lines.get(i).startsWith("#") && ++rows == row) {
                String[] t = lines.get(i).trim().split("\\s+");
                t[0] = String.format(Locale.ROOT, "%.16e", Double.parseDouble(t[0]) + seconds);
                lines.set(i, String.join(" ", t));
                line = i + 1;
            }
        }
        Files.write(file.toPath(), lines, StandardCharsets.UTF_8);
        return line;
    }

    /** Writes odometry.txt, laser.txt, real.txt (and dataset.properties when withMetadata) into dir. */
    public static File write(File dir, double duration, long seed, boolean moving, boolean withMetadata)
            throws IOException {
        dir.mkdirs();
        Playground p = Playground.thesis();
        Rng rng = new Rng(seed);
        double v = moving ? 0.15 : 0.0;
        double omega = moving ? 0.3 : 0.0;
        double step = 0.005;
        double x = START_X;
        double y = START_Y;
        double th = START_THETA;
        double px = x;
        double py = y;
        double pth = th;
        double[] previousGap = new double[p.beaconCount()];
        for (int b = 0; b < previousGap.length; b++) {
            previousGap[b] = Double.NaN;
        }
        try (PrintWriter odo = writer(new File(dir, "odometry.txt"));
                PrintWriter laser = writer(new File(dir, "laser.txt"));
                PrintWriter real = writer(new File(dir, "real.txt"))) {
            int steps = (int) Math.round(duration / step);
            for (int s = 1; s <= steps; s++) {
                double t = s * step;
                double c = Math.cos(th);
                double sn = Math.sin(th);
                x += v * step * c;
                y += v * step * sn;
                th = Angles.wrap2pi(th + omega * step);
                double beam = Angles.wrap2pi(Angles.TWO_PI * 3.0 * t);
                for (int b = 0; b < p.beaconCount(); b++) {
                    double gap = Angles.wrapPi(Angles.bearing(x, y, th, p.beaconX[b], p.beaconY[b]) - beam);
                    // The beam passes the beacon when the gap changes sign from + to - (small jump).
                    if (previousGap[b] > 0 && gap <= 0 && previousGap[b] - gap < 1.0) {
                        double angle = Angles.wrap2pi(Angles.bearing(x, y, th, p.beaconX[b], p.beaconY[b])
                                + 0.01 * rng.gaussian());
                        line(laser, t, angle);
                    }
                    previousGap[b] = gap;
                }
                if (s % 10 == 0) {
                    double ddx = x - px;
                    double ddy = y - py;
                    double cp = Math.cos(pth);
                    double sp = Math.sin(pth);
                    double fx = cp * ddx + sp * ddy + 0.0002 * rng.gaussian();
                    double fy = -sp * ddx + cp * ddy + 0.0002 * rng.gaussian();
                    double ft = Angles.wrapPi(th - pth) + 0.0005 * rng.gaussian();
                    line(odo, t, fx, fy, ft);
                    line(real, t, x, y, th);
                    px = x;
                    py = y;
                    pth = th;
                }
            }
        }
        if (withMetadata) {
            try (PrintWriter m = writer(new File(dir, "dataset.properties"))) {
                m.println("format=jmclbench-dataset/1");
                m.println("scenario=synthetic");
                m.println("seed=" + seed);
                m.println("playground.width=3.0");
                m.println("playground.height=2.0");
                m.println("beacons=0.0,1.0;3.0,0.0;3.0,2.0");
                m.println("start.x=" + START_X);
                m.println("start.y=" + START_Y);
                m.println("start.theta=" + START_THETA);
            }
        }
        return dir;
    }

    private static PrintWriter writer(File f) throws IOException {
        return new PrintWriter(f, StandardCharsets.UTF_8.name());
    }

    private static void line(PrintWriter w, double... v) {
        StringBuilder b = new StringBuilder();
        for (int i = 0; i < v.length; i++) {
            if (i > 0) {
                b.append("  ");
            }
            b.append(String.format(Locale.ROOT, "%.16e", v[i]));
        }
        w.print(b.append('\n'));
    }
}
