package org.jmclbench.scj;

import org.jmclbench.core.mcl.Playground;

/**
 * A {@link SizedMissionInput} whose field and start pose are also known when it is made (the
 * workload's dataset, verification's driver, the tests' logs): the field-and-start half of the
 * interface, once. What is left to a subclass is the sensor log itself.
 */
public abstract class PlacedMissionInput extends SizedMissionInput {
    private final Playground playground;
    private final double startX;
    private final double startY;
    private final double startTheta;

    /** {@code odometry} and {@code laser} events on {@code playground}, the robot starting at (x, y, theta). */
    protected PlacedMissionInput(int odometry, int laser, Playground playground, double startX, double startY,
            double startTheta) {
        super(odometry, laser);
        this.playground = playground;
        this.startX = startX;
        this.startY = startY;
        this.startTheta = startTheta;
    }

    @Override
    public final Playground playground() {
        return playground;
    }

    @Override
    public final double startX() {
        return startX;
    }

    @Override
    public final double startY() {
        return startY;
    }

    @Override
    public final double startTheta() {
        return startTheta;
    }
}
