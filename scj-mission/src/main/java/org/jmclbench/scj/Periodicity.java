package org.jmclbench.scj;

/**
 * The odometry's period: a PeriodicEventHandler needs one, so the mission runs only on odometry
 * whose every reading is within {@link #TOLERANCE_S} of its periodic release, first reading + i *
 * mean interval. Bounding each interval alone would not do: offsets of the same sign add up, and
 * the handler's releases would drift from the logged times (intervals of 50.9 ms then 49.1 ms
 * put the middle of 1000 readings 450 ms off).
 */
public final class Periodicity {
    /** The largest difference between a reading's logged time and its periodic release that still counts as periodic (s). */
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

    /** The first index i >= 1 whose time[i] differs from time[0] + i * period by more than the tolerance, or -1. */
    public static int firstIrregular(double[] time) {
        double p = period(time);
        if (!(p > 0)) {
            return time.length > 1 ? 1 : -1;
        }
        for (int i = 1; i < time.length; i++) {
            if (Math.abs(time[i] - periodicRelease(time, i)) > TOLERANCE_S) {
                return i;
            }
        }
        return -1;
    }

    /** Reading i's periodic release (s): the first reading's time + i * {@link #period}. */
    public static double periodicRelease(double[] time, int i) {
        return time[0] + i * period(time);
    }
}
