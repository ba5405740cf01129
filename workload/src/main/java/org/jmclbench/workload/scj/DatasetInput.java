package org.jmclbench.workload.scj;

import org.jmclbench.scj.PlacedMissionInput;
import org.jmclbench.workload.data.Dataset;

/**
 * The mission's input on Java SE: a dataset read by the workload, or its first events (a
 * warm-up or class-loading prefix). Copies into the mission's arrays; allocates nothing.
 */
public final class DatasetInput extends PlacedMissionInput {
    private final Dataset dataset;

    /** The whole dataset. */
    public DatasetInput(Dataset dataset) {
        this(dataset, dataset.odometryCount(), dataset.laserCount());
    }

    /** The first {@code odometry} odometry and {@code laser} laser events of the dataset. */
    public DatasetInput(Dataset dataset, int odometry, int laser) {
        super(odometry, laser, dataset.playground, dataset.startX, dataset.startY, dataset.startTheta);
        this.dataset = dataset;
    }

    /** The events of the dataset released before {@code seconds} (scaled time is the mission's business). */
    public static DatasetInput before(Dataset d, double seconds) {
        int o = 0;
        while (o < d.odometryCount() && d.odoTime[o] < seconds) {
            o++;
        }
        int l = 0;
        while (l < d.laserCount() && d.laserTime[l] < seconds) {
            l++;
        }
        return new DatasetInput(d, Math.max(1, o), l);
    }

    @Override
    public void readOdometry(double[] time, double[] dx, double[] dy, double[] dtheta) {
        int n = odometryCount();
        System.arraycopy(dataset.odoTime, 0, time, 0, n);
        System.arraycopy(dataset.odoDx, 0, dx, 0, n);
        System.arraycopy(dataset.odoDy, 0, dy, 0, n);
        System.arraycopy(dataset.odoDtheta, 0, dtheta, 0, n);
    }

    @Override
    public void readLaser(double[] time, double[] angle) {
        int n = laserCount();
        System.arraycopy(dataset.laserTime, 0, time, 0, n);
        System.arraycopy(dataset.laserAngle, 0, angle, 0, n);
    }
}
