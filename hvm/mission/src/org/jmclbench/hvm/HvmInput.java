package org.jmclbench.hvm;

import org.jmclbench.core.mcl.Playground;
import org.jmclbench.scj.MissionInput;

/** The mission's input on the HVM: the sensor log, field and start pose from the run file. */
final class HvmInput implements MissionInput {
    private final int odometry;
    private final int laser;
    private final int odoBase;
    private final int laserBase;
    private final Playground playground;
    private final double startX;
    private final double startY;
    private final double startTheta;

    /** Reads the data part of the run file, which starts at word {@code at}. */
    HvmInput(int at) {
        odometry = (int) HvmData.word(at);
        laser = (int) HvmData.word(at + 1);
        double width = HvmData.real(at + 2);
        double height = HvmData.real(at + 3);
        int beacons = (int) HvmData.word(at + 4);
        double[] bx = new double[beacons];
        double[] by = new double[beacons];
        int w = at + 5;
        for (int b = 0; b < beacons; b++) {
            bx[b] = HvmData.real(w++);
        }
        for (int b = 0; b < beacons; b++) {
            by[b] = HvmData.real(w++);
        }
        playground = new Playground(width, height, bx, by);
        startX = HvmData.real(w++);
        startY = HvmData.real(w++);
        startTheta = HvmData.real(w++);
        odoBase = w;
        laserBase = w + 4 * odometry;
    }

    @Override
    public int odometryCount() {
        return odometry;
    }

    @Override
    public int laserCount() {
        return laser;
    }

    @Override
    public void readOdometry(double[] time, double[] dx, double[] dy, double[] dtheta) {
        fill(time, odoBase, odometry);
        fill(dx, odoBase + odometry, odometry);
        fill(dy, odoBase + 2 * odometry, odometry);
        fill(dtheta, odoBase + 3 * odometry, odometry);
    }

    @Override
    public void readLaser(double[] time, double[] angle) {
        fill(time, laserBase, laser);
        fill(angle, laserBase + laser, laser);
    }

    private static void fill(double[] dest, int from, int n) {
        for (int i = 0; i < n; i++) {
            dest[i] = HvmData.real(from + i);
        }
    }

    @Override
    public Playground playground() {
        return playground;
    }

    @Override
    public double startX() {
        return startX;
    }

    @Override
    public double startY() {
        return startY;
    }

    @Override
    public double startTheta() {
        return startTheta;
    }
}
