package org.jmclbench.scj;

import org.jmclbench.core.mcl.Angles;
import org.jmclbench.core.mcl.Playground;

/**
 * A small noiseless sensor log for tests: the robot drives a slow circle on the thesis's field,
 * odometry every 50 ms, and the laser sees the beacons in turn every 110 ms, offset by 25 ms so
 * that no laser event ties with an odometry event.
 */
final class SyntheticInput extends PlacedMissionInput {
    static final double PERIOD = 0.050;
    private final double[] odoTime;
    private final double[] odoDx;
    private final double[] odoDy;
    private final double[] odoDtheta;
    private final double[] laserTime;
    private final double[] laserAngle;

    SyntheticInput(double seconds) {
        super((int) Math.round(seconds / PERIOD), (int) ((seconds - 0.025) / 0.110), Playground.thesis(), 1.5, 0.6, 0.0);
        int odo = odometryCount();
        odoTime = new double[odo];
        odoDx = new double[odo];
        odoDy = new double[odo];
        odoDtheta = new double[odo];
        double speed = 0.2; // m/s
        double turn = 0.3; // rad/s
        for (int i = 0; i < odo; i++) {
            odoTime[i] = (i + 1) * PERIOD;
            odoDx[i] = speed * PERIOD;
            odoDtheta[i] = turn * PERIOD;
        }
        int laser = laserCount();
        laserTime = new double[laser];
        laserAngle = new double[laser];
        for (int j = 0; j < laser; j++) {
            double t = 0.025 + j * 0.110;
            laserTime[j] = t;
            // The true pose at t: integrate the odometry applied so far (as the robot moved by then).
            double x = startX();
            double y = startY();
            double th = startTheta();
            for (int i = 0; i < odo && odoTime[i] <= t; i++) {
                x += odoDx[i] * Math.cos(th);
                y += odoDx[i] * Math.sin(th);
                th = Angles.wrap2pi(th + odoDtheta[i]);
            }
            int b = j % 3;
            laserAngle[j] = Angles.bearing(x, y, th, playground().beaconX[b], playground().beaconY[b]);
        }
    }

    @Override
    public void readOdometry(double[] time, double[] dx, double[] dy, double[] dtheta) {
        System.arraycopy(odoTime, 0, time, 0, odoTime.length);
        System.arraycopy(odoDx, 0, dx, 0, odoDx.length);
        System.arraycopy(odoDy, 0, dy, 0, odoDy.length);
        System.arraycopy(odoDtheta, 0, dtheta, 0, odoDtheta.length);
    }

    @Override
    public void readLaser(double[] time, double[] angle) {
        System.arraycopy(laserTime, 0, time, 0, laserTime.length);
        System.arraycopy(laserAngle, 0, angle, 0, laserAngle.length);
    }
}
