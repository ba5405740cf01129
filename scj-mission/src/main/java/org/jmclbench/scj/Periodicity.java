package org.jmclbench.scj;

/**
 * The odometry's period: a PeriodicEventHandler needs one, so the mission runs only on odometry
 * whose every interval is within {@link #TOLERANCE_S} of the mean interval.
 */
public final class Periodicity {
    /** The largest difference between an odometry interval and the period that still counts as periodic (s). */
    public static final double TOLERANCE_S = 0.001;
    /** The period assumed for a single odometry event (s): the thesis's 50 ms. */
    public static final double DEFAULT_PERIOD_S = 0.050;

    private Periodicity() {
    }

    /** The mean interval of the odometry times (s), or {@link #DEFAULT_PERIOD_S} for fewer than two. */
    public static double period(double[] time) {
        int n = time.length;
        return n < 2 ? DEFAULT_PERIOD_S : (time[n - 1] - time[0]) / (n - 1);
    }

    /** The first index i >= 1 whose interval time[i] - time[i-1] differs from the period by more than the tolerance, or -1. */
    public static int firstIrregular(double[] time) {
        double p = period(time);
        if (!(p > 0)) {
            return time.length > 1 ? 1 : -1;
        }
        for (int i = 1; i < time.length; i++) {
            if (Math.abs(time[i] - time[i - 1] - p) > TOLERANCE_S) {
                return i;
            }
        }
        return -1;
    }
}
