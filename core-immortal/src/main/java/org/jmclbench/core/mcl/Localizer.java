package org.jmclbench.core.mcl;

/**
 * The robot's Monte-Carlo localizer (docs/ALGORITHM.md): one shared resource on which at
 * most one job works at a time. A job either completes and commits its result, or is
 * aborted and changes nothing (particles, estimate, covariance and random generator).
 * Not thread-safe: the caller serialises jobs.
 */
public interface Localizer {
    /** Odometry job (ALGORITHM 6): false when aborted, the state then unchanged. */
    boolean predict(double dx, double dy, double dtheta, AbortSignal abort);

    /** Laser job (ALGORITHM 7) for a measured angle in [0, 2pi): false when aborted, the state then unchanged. */
    boolean update(double angle, AbortSignal abort);

    /** The x of the estimated pose committed by the last completed job (m). */
    double estimateX();

    /** The y of the estimated pose committed by the last completed job (m). */
    double estimateY();

    /** The heading of the estimated pose committed by the last completed job (rad, in [0, 2pi)). */
    double estimateTheta();

    /**
     * Copies the covariance of the last completed update into {@code out[0..5]} as cxx cxy
     * cxt cyy cyt ctt; zeros before the first update or when the covariance is not computed.
     */
    void covariance(double[] out);

    /** The particle count N. */
    int particleCount();

    /** Copies particle i's pose into {@code out[0..2]} (x, y, theta); for tests and tools, not timed code. */
    void particle(int i, double[] out);
}
