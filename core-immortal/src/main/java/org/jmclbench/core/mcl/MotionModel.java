package org.jmclbench.core.mcl;

/** The constants of the motion and sensor models (docs/ALGORITHM.md sections 5 to 8), shared by both memory styles. */
public final class MotionModel {
    /** Standard deviation of the known-start spread in x, y (m) and theta (rad). */
    public static final double INIT_SIGMA = 0.05;
    public static final double ALPHA_XY = 0.10;
    public static final double FLOOR_XY = 0.002;
    public static final double ALPHA_THETA = 0.10;
    public static final double ALPHA_THETA_XY = 0.05;
    public static final double FLOOR_THETA = 0.004;
    /** Particles processed between two polls of the abort signal: the default of {@link MclConfig#pollInterval}. */
    public static final int ABORT_BLOCK = 64;

    private MotionModel() {
    }

    /** Translation noise for an increment of length d: ALPHA_XY * d + FLOOR_XY. */
    public static double sigmaXY(double d) {
        return ALPHA_XY * d + FLOOR_XY;
    }

    /** Rotation noise: ALPHA_THETA * |dtheta| + ALPHA_THETA_XY * d + FLOOR_THETA, summed left to right. */
    public static double sigmaTheta(double d, double dtheta) {
        return ALPHA_THETA * Math.abs(dtheta) + ALPHA_THETA_XY * d + FLOOR_THETA;
    }
}
