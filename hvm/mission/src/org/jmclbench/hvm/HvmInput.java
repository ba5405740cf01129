package org.jmclbench.hvm;

import org.jmclbench.core.mcl.Playground;
import org.jmclbench.scj.SizedMissionInput;

/** The mission's input on the HVM: the sensor log, field and start pose from the run file. */
final class HvmInput extends SizedMissionInput {
    private final int odoBase;
    private final int laserBase;
    private final Playground playground;
    private final double startX;
    private final double startY;
    private final double startTheta;

    /** Reads the data part of the run file, which starts at word {@code at}. */
    HvmInput(int at) {
        super((int) HvmData.word(at), (int) HvmData.word(at + 1));
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
        laserBase = w + 4 * odometryCount();
    }

    @Override
    public void readOdometry(double[] time, double[] dx, double[] dy, double[] dtheta) {
        int n = odometryCount();
        fill(time, odoBase, n);
        fill(dx, odoBase + n, n);
        fill(dy, odoBase + 2 * n, n);
        fill(dtheta, odoBase + 3 * n, n);
    }

    @Override
    public void readLaser(double[] time, double[] angle) {
        int n = laserCount();
        fill(time, laserBase, n);
        fill(angle, laserBase + n, n);
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
