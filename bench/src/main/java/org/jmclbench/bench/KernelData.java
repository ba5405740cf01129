package org.jmclbench.bench;

import java.io.BufferedReader;
import java.io.File;
import java.io.FileInputStream;
import java.io.IOException;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import java.util.Properties;
import org.jmclbench.workload.mcl.Playground;

/**
 * The events of one shipped dataset as flat arrays, read once before measuring: the kernel
 * benchmarks replay them so that Java and the C timing loop do the same work on the same data.
 */
final class KernelData {
    /** Odometry increments: dx, dy, dtheta of event k at 3k, 3k+1, 3k+2. */
    final double[] odometry;
    /** Laser angles, in event order. */
    final double[] laser;
    final Playground playground;
    final double startX;
    final double startY;
    final double startTheta;

    private KernelData(double[] odometry, double[] laser, Playground playground, double x, double y, double theta) {
        this.odometry = odometry;
        this.laser = laser;
        this.playground = playground;
        this.startX = x;
        this.startY = y;
        this.startTheta = theta;
    }

    int odometryCount() {
        return odometry.length / 3;
    }

    /** Reads dataset folder dir; an empty name means datasets/match-short found upwards from the working directory. */
    static KernelData load(String dir) throws IOException {
        File folder = dir.isEmpty() ? findDefault() : new File(dir);
        List<double[]> odo = readColumns(new File(folder, "odometry.txt"), 4);
        List<double[]> las = readColumns(new File(folder, "laser.txt"), 2);
        List<double[]> real = readColumns(new File(folder, "real.txt"), 4);
        double[] o = new double[odo.size() * 3];
        for (int k = 0; k < odo.size(); k++) {
            System.arraycopy(odo.get(k), 1, o, 3 * k, 3);
        }
        double[] a = new double[las.size()];
        for (int k = 0; k < las.size(); k++) {
            a[k] = las.get(k)[1];
        }
        Properties p = new Properties();
        File props = new File(folder, "dataset.properties");
        Playground pg = Playground.thesis();
        double x = real.get(0)[1];
        double y = real.get(0)[2];
        double t = real.get(0)[3];
        if (props.isFile()) {
            try (FileInputStream in = new FileInputStream(props)) {
                p.load(in);
            }
            x = Double.parseDouble(p.getProperty("start.x", Double.toString(x)));
            y = Double.parseDouble(p.getProperty("start.y", Double.toString(y)));
            t = Double.parseDouble(p.getProperty("start.theta", Double.toString(t)));
            String beacons = p.getProperty("beacons");
            if (beacons != null) {
                String[] pairs = beacons.split(";");
                double[] bx = new double[pairs.length];
                double[] by = new double[pairs.length];
                for (int i = 0; i < pairs.length; i++) {
                    String[] xy = pairs[i].split(",");
                    bx[i] = Double.parseDouble(xy[0].trim());
                    by[i] = Double.parseDouble(xy[1].trim());
                }
                pg = new Playground(Double.parseDouble(p.getProperty("playground.width", "3.0")),
                        Double.parseDouble(p.getProperty("playground.height", "2.0")), bx, by);
            }
        }
        if (o.length == 0 || a.length == 0) {
            throw new IOException(folder + ": no odometry or no laser events");
        }
        return new KernelData(o, a, pg, x, y, t);
    }

    private static File findDefault() throws IOException {
        File dir = new File("").getAbsoluteFile();
        while (dir != null) {
            File c = new File(dir, "datasets/match-short");
            if (new File(c, "odometry.txt").isFile()) {
                return c;
            }
            dir = dir.getParentFile();
        }
        throw new IOException("datasets/match-short not found above " + new File("").getAbsolutePath()
                + "; pass -p dataset=DIR");
    }

    private static List<double[]> readColumns(File f, int cols) throws IOException {
        List<double[]> rows = new ArrayList<>();
        try (BufferedReader r = new BufferedReader(new InputStreamReader(new FileInputStream(f), StandardCharsets.UTF_8))) {
            String line;
            int no = 0;
            while ((line = r.readLine()) != null) {
                no++;
                line = line.trim();
                if (line.isEmpty() || line.startsWith("#")) {
                    continue;
                }
                String[] t = line.split("\\s+");
                if (t.length != cols) {
                    throw new IOException(f + ":" + no + ": expected " + cols + " columns, found " + t.length);
                }
                double[] row = new double[cols];
                for (int i = 0; i < cols; i++) {
                    row[i] = Double.parseDouble(t[i]);
                }
                rows.add(row);
            }
        }
        return rows;
    }
}
