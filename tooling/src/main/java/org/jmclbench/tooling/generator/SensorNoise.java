package org.jmclbench.tooling.generator;

/**
 * The sensor noise the simulator adds. Odometry: each increment gets Gaussian noise with
 * {@code sigmaXY = alphaXY * d + floorXY} on dx and dy and
 * {@code sigmaTheta = alphaTheta * |dtheta| + alphaThetaXY * d + floorTheta} on dtheta
 * (d the true distance travelled). Laser: Gaussian angle noise {@code laserSigma} and a
 * probability {@code missProbability} that a beam crossing is not reported.
 */
public record SensorNoise(double alphaXY, double floorXY, double alphaTheta, double alphaThetaXY,
        double floorTheta, double laserSigma, double missProbability) {

    /**
     * The shipped datasets' noise: a little smaller than the MCL motion model of
     * ALGORITHM.md section 6, so that the filter's model covers the real error.
     */
    public static final SensorNoise DEFAULT = new SensorNoise(0.03, 0.0002, 0.03, 0.02, 0.0005, 0.01, 0.05);

    /** No noise and no missed detections: the sensors report the truth (for tests). */
    public static final SensorNoise NONE = new SensorNoise(0, 0, 0, 0, 0, 0, 0);
}
