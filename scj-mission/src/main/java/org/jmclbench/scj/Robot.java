package org.jmclbench.scj;

import org.jmclbench.core.mcl.AbortSignal;
import org.jmclbench.core.mcl.Localizer;
import org.jmclbench.core.record.JobRecords;

/**
 * The robot: the one shared resource the predict and update jobs work on, one at a time (its
 * methods are synchronized; under SCJ Level 1 by priority ceiling emulation). A job either
 * completes and commits its estimate into the event's record, or is aborted and changes nothing.
 * Not final: a verification test replaces it (see {@link MissionConfiguration#newRobot}).
 */
public class Robot {
    protected final Localizer localizer;
    protected final ImmortalEntry entry;
    private final double[] covariance = new double[6];

    public Robot(Localizer localizer, ImmortalEntry entry) {
        this.localizer = localizer;
        this.entry = entry;
    }

    /** The predict job of merged event k (an odometry event); false when aborted, the robot then unchanged. */
    public synchronized boolean predict(int k, AbortSignal abort) {
        int i = entry.timeline.taskIndex(k);
        if (!localizer.predict(entry.odoDx[i], entry.odoDy[i], entry.odoDtheta[i], abort)) {
            return false;
        }
        commit(k, false);
        return true;
    }

    /** The update job of merged event k (a laser event); false when aborted, the robot then unchanged. */
    public synchronized boolean update(int k, AbortSignal abort) {
        int j = entry.timeline.taskIndex(k);
        if (!localizer.update(entry.laserAngle[j], abort)) {
            return false;
        }
        commit(k, true);
        return true;
    }

    /** The localizer (for tests and the initial estimate; jobs go through predict and update). */
    public Localizer localizer() {
        return localizer;
    }

    private void commit(int k, boolean update) {
        JobRecords r = entry.records;
        r.estX[k] = localizer.estimateX();
        r.estY[k] = localizer.estimateY();
        r.estTheta[k] = localizer.estimateTheta();
        if (update && r.cov != null) {
            localizer.covariance(covariance);
            for (int c = 0; c < 6; c++) {
                r.cov[6 * k + c] = covariance[c];
            }
        }
    }
}
