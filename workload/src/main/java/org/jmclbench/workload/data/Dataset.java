package org.jmclbench.workload.data;

import org.jmclbench.core.record.Deviation;
import org.jmclbench.core.record.JobRecords;
import org.jmclbench.core.timeline.Timeline;

import java.io.File;
import java.util.Properties;

import org.jmclbench.core.mcl.Playground;
import org.jmclbench.workload.BadInputException;

/** One recorded run of the robot (docs/FORMATS.md section 1): odometry, laser and ground truth, by columns. */
public final class Dataset {
    /** Odometry event times (s) and increments in the robot frame (m, m, rad). */
    public final double[] odoTime;
    public final double[] odoDx;
    public final double[] odoDy;
    public final double[] odoDtheta;
    /** Laser event times (s) and measured beacon angles relative to the heading (rad). */
    public final double[] laserTime;
    public final double[] laserAngle;
    /** Ground-truth times (s) and poses. */
    public final double[] realTime;
    public final double[] realX;
    public final double[] realY;
    public final double[] realTheta;
    /** The field and its beacons (the thesis's when the metadata does not say). */
    public final Playground playground;
    /** The known start pose: from the metadata, else the first ground-truth line. */
    public final double startX;
    public final double startY;
    public final double startTheta;
    /** The metadata (empty for bare thesis-format files); never modified after reading. */
    public final Properties metadata;
    /** A short name: the scenario, else the folder or odometry file name. */
    public final String name;
    /** The dataset folder, or null for bare files. */
    public final File folder;
    /** The three data files as read. */
    public final File odometryFile;
    public final File laserFile;
    public final File realFile;

    Dataset(double[][] odo, double[][] laser, double[][] real, Playground playground, double startX,
            double startY, double startTheta, Properties metadata, String name, File folder, File odometryFile,
            File laserFile, File realFile) {
        this.odoTime = odo[0];
        this.odoDx = odo[1];
        this.odoDy = odo[2];
        this.odoDtheta = odo[3];
        this.laserTime = laser[0];
        this.laserAngle = laser[1];
        this.realTime = real[0];
        this.realX = real[1];
        this.realY = real[2];
        this.realTheta = real[3];
        this.playground = playground;
        this.startX = startX;
        this.startY = startY;
        this.startTheta = startTheta;
        this.metadata = metadata;
        this.name = name;
        this.folder = folder;
        this.odometryFile = odometryFile;
        this.laserFile = laserFile;
        this.realFile = realFile;
    }

    /** The scenario named in the metadata, or null. */
    public String scenario() {
        return metadata.getProperty("scenario");
    }

    /** Number of odometry events. */
    public int odometryCount() {
        return odoTime.length;
    }

    /** Number of laser events. */
    public int laserCount() {
        return laserTime.length;
    }

    /** Number of ground-truth poses. */
    public int realCount() {
        return realTime.length;
    }

    /** Time of the last event or pose (s). */
    public double duration() {
        double d = 0;
        if (odoTime.length > 0) {
            d = Math.max(d, odoTime[odoTime.length - 1]);
        }
        if (laserTime.length > 0) {
            d = Math.max(d, laserTime[laserTime.length - 1]);
        }
        if (realTime.length > 0) {
            d = Math.max(d, realTime[realTime.length - 1]);
        }
        return d;
    }

    /**
     * Refuses a time scale that takes an event past a run's largest time, DataGrammar.VALUE_MAX
     * seconds (docs/FORMATS.md 2): each time is within it, but times 1000 of them may not be, and
     * their nanoseconds would overflow the 64-bit release times. The C baseline's
     * jm_dataset_check_time_scale.
     */
    public void checkTimeScale(double timeScale) throws BadInputException {
        checkScaled(odoTime, odometryFile, timeScale);
        checkScaled(laserTime, laserFile, timeScale);
    }

    /**
     * Refuses a warm-up that reaches the data's last event (docs/FORMATS.md 2): the warm-up replays
     * the first S seconds of data (times before S, unscaled), so one at or past the last event is
     * no first part but the whole dataset, and summary.json's warmupS would claim seconds that
     * were never replayed. Named after the file whose last time is the later (odometry on a tie).
     * The C baseline's jm_dataset_check_warmup.
     */
    public void checkWarmup(double warmupS) throws BadInputException {
        double odoLast = odoTime[odoTime.length - 1];
        double laserLast = laserTime[laserTime.length - 1];
        if (warmupS > 0 && warmupS >= Math.max(odoLast, laserLast)) {
            File last = odoLast >= laserLast ? odometryFile : laserFile;
            throw BadInputException.ofOption("--warmup", "reaches the last time of " + last.getPath()
                    + ": a warm-up replays the data before it and must leave an event after it");
        }
    }

    private static void checkScaled(double[] time, File file, double timeScale) throws BadInputException {
        if (time[time.length - 1] * timeScale > DataGrammar.VALUE_MAX) {
            throw BadInputException.ofOption("--time-scale", "scales the last time of " + file.getPath() + " past "
                    + DataGrammar.VALUE_MAX_TEXT + " s, the largest time of a run");
        }
    }

    /** The odometry and laser events merged by time, as the dispatcher releases them. */
    public Timeline timeline() {
        return Timeline.merge(odoTime, laserTime);
    }

    /** The localisation error of a run's records against this dataset's ground truth. */
    public Deviation deviation(Timeline t, JobRecords r) {
        return Deviation.of(realTime, realX, realY, realTheta, t, r);
    }
}
