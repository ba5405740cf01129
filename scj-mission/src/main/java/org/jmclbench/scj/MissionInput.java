package org.jmclbench.scj;

import org.jmclbench.core.mcl.Playground;

/**
 * Where the mission's data comes from: the sensor log (odometry and laser events), the field and
 * the known start pose. The one seam between the mission and the platform it runs on: on Java SE
 * the workload supplies it from the dataset files, on an SCJ VM its own natives do (the HVM hands
 * doubles over as raw long bits). Called only while the application initialises (in immortal
 * memory); the fill methods write into arrays the mission allocated and must not allocate.
 */
public interface MissionInput {
    /** The number of odometry events (at least 1). */
    int odometryCount();

    /** The number of laser events. */
    int laserCount();

    /** Fills time (s, from the run start, ascending) and the increments dx, dy, dtheta (m, m, rad) of every odometry event. */
    void readOdometry(double[] time, double[] dx, double[] dy, double[] dtheta);

    /** Fills time (s, ascending) and the measured beacon angle (rad, in [0, 2pi)) of every laser event. */
    void readLaser(double[] time, double[] angle);

    /** The field and its beacons. */
    Playground playground();

    /** The known start pose's x (m), used by the {@code known} initialisation. */
    double startX();

    /** The known start pose's y (m). */
    double startY();

    /** The known start pose's heading (rad). */
    double startTheta();
}
