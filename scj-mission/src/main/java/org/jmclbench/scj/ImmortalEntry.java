package org.jmclbench.scj;

import org.jmclbench.core.mcl.Playground;
import org.jmclbench.core.record.JobRecords;
import org.jmclbench.core.timeline.Timeline;

/**
 * The state that lives for the whole program, created in immortal memory while the application
 * initialises: the sensor log read from the {@link MissionInput}, the merged timeline, every
 * event's scheduled release and deadline, and the job records the handlers fill in.
 */
public final class ImmortalEntry {
    /** Odometry times (s) and increments. */
    public final double[] odoTime;
    public final double[] odoDx;
    public final double[] odoDy;
    public final double[] odoDtheta;
    /** Laser times (s) and measured angles. */
    public final double[] laserTime;
    public final double[] laserAngle;
    public final Playground playground;
    public final double startX;
    public final double startY;
    public final double startTheta;
    /** The events merged by time (ties: odometry first), as in the Java SE engine. */
    public final Timeline timeline;
    /** The merged event index of the i-th odometry event and of the j-th laser event. */
    public final int[] odoEvent;
    public final int[] laserEvent;
    /** The odometry period, and so the predict handler's period and relative deadline (ns, scaled). */
    public final long periodNs;
    /** Each event's scheduled release and absolute deadline, ns from the mission start (scaled). */
    public final long[] releaseNs;
    public final long[] deadlineNs;
    /** Every job's times, outcome and committed estimate. */
    public final JobRecords records;

    /** Reads the input and lays out the schedule; allocates only here, in immortal memory. */
    public ImmortalEntry(MissionInput input, MissionConfiguration config) {
        int odo = input.odometryCount();
        int laser = input.laserCount();
        if (odo < 1) {
            throw new IllegalArgumentException("the mission needs odometry: its period drives the predict handler");
        }
        odoTime = new double[odo];
        odoDx = new double[odo];
        odoDy = new double[odo];
        odoDtheta = new double[odo];
        laserTime = new double[laser];
        laserAngle = new double[laser];
        input.readOdometry(odoTime, odoDx, odoDy, odoDtheta);
        input.readLaser(laserTime, laserAngle);
        playground = input.playground();
        startX = input.startX();
        startY = input.startY();
        startTheta = input.startTheta();
        timeline = Timeline.merge(odoTime, laserTime);
        int n = timeline.size();
        odoEvent = new int[odo];
        laserEvent = new int[laser];
        for (int k = 0; k < n; k++) {
            if (timeline.task(k) == Timeline.PREDICT) {
                odoEvent[timeline.taskIndex(k)] = k;
            } else {
                laserEvent[timeline.taskIndex(k)] = k;
            }
        }
        double scale = config.timeScale;
        periodNs = toNs(Periodicity.period(odoTime), scale);
        long firstOdoNs = toNs(odoTime[0], scale);
        releaseNs = new long[n];
        deadlineNs = new long[n];
        for (int i = 0; i < odo; i++) {
            // The periodic handler is released at start + i * period, not at the logged time
            // (each logged time is within Periodicity.TOLERANCE_S of it, checked before the
            // mission runs).
            int k = odoEvent[i];
            releaseNs[k] = firstOdoNs + i * periodNs;
            deadlineNs[k] = releaseNs[k] + periodNs;
        }
        for (int j = 0; j < laser; j++) {
            int k = laserEvent[j];
            releaseNs[k] = toNs(laserTime[j], scale);
        }
        for (int j = 0; j < laser; j++) {
            // An update is due when the next laser event arrives; the last one a revolution's longest gap later.
            int k = laserEvent[j];
            deadlineNs[k] = j + 1 < laser ? releaseNs[laserEvent[j + 1]] : releaseNs[k] + toNs(LAST_UPDATE_DEADLINE_S, scale);
        }
        records = new JobRecords(timeline, config.mcl.covariance);
    }

    /** Relative deadline of the last update job (s), as in the Java SE engine. */
    public static final double LAST_UPDATE_DEADLINE_S = 0.250;

    /** Seconds (times the time scale) to ns, rounded half up; times are never negative. */
    static long toNs(double seconds, double scale) {
        return (long) Math.floor(seconds * scale * 1e9 + 0.5);
    }

    /** The number of events. */
    public int size() {
        return releaseNs.length;
    }
}
