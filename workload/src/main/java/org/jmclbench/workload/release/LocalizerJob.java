package org.jmclbench.workload.release;

import org.jmclbench.workload.data.Dataset;
import org.jmclbench.core.timeline.Timeline;
import org.jmclbench.core.mcl.AbortSignal;
import org.jmclbench.core.mcl.Localizer;
import org.jmclbench.core.record.JobRecords;

/**
 * The MCL job of an event: predict with the odometry increment or update with the laser angle,
 * then, when the job completed, the committed estimate (and covariance) into the records.
 * Allocation-free; runs on the handler that holds the robot, so no other job can interleave.
 */
public final class LocalizerJob implements EventJob {
    private final double[] odoDx;
    private final double[] odoDy;
    private final double[] odoDtheta;
    private final double[] laserAngle;
    private final Timeline timeline;
    private final Localizer localizer;
    private final JobRecords records;
    private final double[] covariance = new double[6];

    public LocalizerJob(Dataset dataset, Timeline timeline, Localizer localizer, JobRecords records) {
        this(dataset.odoDx, dataset.odoDy, dataset.odoDtheta, dataset.laserAngle, timeline, localizer, records);
    }

    /** A job on explicit event data: odometry increments and laser angles by task index. */
    public LocalizerJob(double[] odoDx, double[] odoDy, double[] odoDtheta, double[] laserAngle,
                        Timeline timeline, Localizer localizer, JobRecords records) {
        this.odoDx = odoDx;
        this.odoDy = odoDy;
        this.odoDtheta = odoDtheta;
        this.laserAngle = laserAngle;
        this.timeline = timeline;
        this.localizer = localizer;
        this.records = records;
    }

    @Override
    public boolean run(int k, AbortSignal abort) {
        if (!step(k, abort)) {
            return false;
        }
        commitEstimate(k);
        return true;
    }

    /** Event k's predict or update alone, recording nothing; false when aborted. */
    public boolean step(int k, AbortSignal abort) {
        int i = timeline.taskIndex(k);
        return timeline.task(k) == Timeline.UPDATE
                ? localizer.update(laserAngle[i], abort)
                : localizer.predict(odoDx[i], odoDy[i], odoDtheta[i], abort);
    }

    /** The localizer's estimate (and, after an update, its covariance) into the records as event k's. */
    public void commitEstimate(int k) {
        JobRecords r = records;
        r.estX[k] = localizer.estimateX();
        r.estY[k] = localizer.estimateY();
        r.estTheta[k] = localizer.estimateTheta();
        if (r.cov != null && timeline.task(k) == Timeline.UPDATE) {
            localizer.covariance(covariance);
            System.arraycopy(covariance, 0, r.cov, 6 * k, 6);
        }
    }
}
