package org.jmclbench.verification.seeded;

/**
 * Terminable job code for the static abort-poll check: loops that poll in the ways the mission
 * does (every 64 particles, once per block), and seeded loops that do not, marked VIOLATION.
 */
public final class PollingJob {
    private final double[] x = new double[256];
    private final double[] w = new double[256];

    /** Polls every 64 particles inside the loop: fine. */
    public boolean predict(double dx, AbortSignal abort) {
        for (int i = 0; i < x.length; i++) {
            if ((i & 63) == 0 && abort.abortRequested()) {
                return false;
            }
            x[i] += dx;
        }
        return true;
    }

    /** Polls once per block of 64 in an enclosing loop: fine. */
    public boolean blocks(AbortSignal abort) {
        for (int b = 0; b < x.length; b += 64) {
            if (abort.abortRequested()) {
                return false;
            }
            for (int i = b; i < Math.min(b + 64, x.length); i++) {
                x[i] *= 2;
            }
        }
        return true;
    }

    /** The first loop polls; the normalisation after it does not (seeded). */
    public boolean update(AbortSignal abort) {
        double total = 0;
        for (int i = 0; i < w.length; i++) {
            if ((i & 63) == 0 && abort.abortRequested()) {
                return false;
            }
            total += w[i];
        }
        for (int i = 0; i < w.length; i++) { // VIOLATION
            w[i] /= total;
        }
        // A loop over a constant count (not the particles) needs no poll.
        for (int j = 0; j < 6; j++) {
            x[j] = 0;
        }
        return true;
    }

    /** A block loop whose poll sits in a sibling loop does not cover the second inner loop (seeded). */
    public boolean siblings(AbortSignal abort) {
        for (int b = 0; b < x.length; b += 64) {
            for (int i = b; i < b + 64; i++) {
                if (abort.abortRequested()) {
                    return false;
                }
            }
            int k = b;
            while (k < b + 64) { // VIOLATION
                x[k++] = 0;
            }
        }
        return true;
    }

    /**
     * Systematic resampling as two nested loops, as the mission had it: the walk over the old
     * particles goes on across placings, so one placing may pass all of them between two polls (seeded).
     */
    public boolean walk(double u, int[] out, AbortSignal abort) {
        double c = w[0];
        int i = 0;
        for (int m = 0; m < w.length; m++) {
            if ((m & 63) == 0 && abort.abortRequested()) {
                return false;
            }
            double t = u + (double) m / w.length;
            while (t > c && i < w.length - 1) { // VIOLATION
                i++;
                c += w[i];
            }
            out[m] = i;
        }
        return true;
    }

    /** Polls every fourth interval, as a mask of {@code (pollMask << 2) | 3} does (seeded). */
    public boolean wide(AbortSignal abort, int pollMask) {
        for (int i = 0; i < x.length; i++) { // VIOLATION
            if ((i & ((pollMask << 2) | 3)) == 0 && abort.abortRequested()) {
                return false;
            }
            x[i] += 1;
        }
        return true;
    }

    /** Polls every 128 particles, a constant stride over the interval of 64 (seeded). */
    public boolean sparse(AbortSignal abort) {
        for (int i = 0; i < x.length; i++) { // VIOLATION
            if (i % 128 == 0 && abort.abortRequested()) {
                return false;
            }
            x[i] -= 1;
        }
        return true;
    }

    /** Between two polling steps calls a helper whose particle loop does not poll (seeded, in the helper). */
    public boolean callsUnpolledHelper(AbortSignal abort) {
        if (!predict(1.0, abort)) {
            return false;
        }
        normalise();
        return predict(-1.0, abort);
    }

    /** Takes no signal, but runs in a terminable job, outside any particle loop. */
    private void normalise() {
        for (int i = 0; i < w.length; i++) { // VIOLATION
            w[i] /= 2;
        }
    }

    /** A helper called from inside a polling particle loop is part of one particle step: fine. */
    public boolean perParticle(AbortSignal abort, int pollMask) {
        for (int i = 0; i < x.length; i++) {
            if ((i & pollMask) == 0 && abort.abortRequested()) {
                return false;
            }
            x[i] = beacons(x[i]);
        }
        return true;
    }

    private double beacons(double v) {
        double s = 0;
        for (int b = 0; b < w.length; b++) {
            s += w[b] * v;
        }
        return s;
    }

    /** Not terminable (no AbortSignal, called by no terminable code): its loops are not looked at. */
    public double sum() {
        double s = 0;
        for (int i = 0; i < x.length; i++) {
            s += x[i];
        }
        return s;
    }
}
