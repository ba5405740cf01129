package org.jmclbench.verification.toy;

/** The shared robot: particles and an estimate, changed only by a completed job's commit. */
final class ToyRobot {
    private double[] x;
    private double[] spare;
    private double estimate;

    ToyRobot(int particles) {
        x = new double[particles];
        spare = new double[particles];
        for (int i = 0; i < particles; i++) {
            x[i] = i;
        }
    }

    int particles() {
        return x.length;
    }

    synchronized double particle(int i) {
        return x[i];
    }

    /** The job's scratch buffer (only the handler thread touches it). */
    double[] spare() {
        return spare;
    }

    /** The live particles, for the seeded bug that writes them before its poll. */
    synchronized void overwriteLive(int i, double v) {
        x[i] = v;
    }

    synchronized void commit(double est, ToyMission m, int e) {
        double[] t = x;
        x = spare;
        spare = t;
        estimate = est;
        // The outcome is recorded under the robot's lock (robot, then records: the lock order).
        m.end(e, ToyMission.PROCESSED);
    }

    synchronized double estimate() {
        return estimate;
    }

    double estimateUnguarded() {
        return estimate;
    }

    /** Every bit of the state a job may change (P3 compares it before and after an aborted job). */
    synchronized long fingerprint() {
        long h = Double.doubleToRawLongBits(estimate);
        for (int i = 0; i < x.length; i++) {
            h = h * 31 + Double.doubleToRawLongBits(x[i]);
        }
        return h;
    }
}
