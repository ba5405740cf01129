package org.jmclbench.scj;

/**
 * A {@link MissionInput} whose event counts are known when it is made (every platform's input
 * is: the workload's dataset, the HVM's run file): the counts half of the interface, once.
 */
public abstract class SizedMissionInput implements MissionInput {
    private final int odometry;
    private final int laser;

    /** {@code odometry} odometry and {@code laser} laser events. */
    protected SizedMissionInput(int odometry, int laser) {
        this.odometry = odometry;
        this.laser = laser;
    }

    @Override
    public final int odometryCount() {
        return odometry;
    }

    @Override
    public final int laserCount() {
        return laser;
    }
}
