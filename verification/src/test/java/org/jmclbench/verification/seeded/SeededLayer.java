package org.jmclbench.verification.seeded;

/**
 * Stands for the SCJ layer in the static allocation check's seeded release: code the release
 * calls but that is not the job's, looked at from the call.
 */
final class SeededLayer {
    private SeededLayer() {
    }

    /** Allocates only the exception of its error path: a release may call it. */
    static void clear(double[] p) {
        if (p == null) {
            throw new IllegalArgumentException("no particles");
        }
        for (int i = 0; i < p.length; i++) {
            p[i] = 0;
        }
    }

    /** Allocates a copy: a release that calls it allocates. */
    static double[] snapshot(double[] p) {
        double[] copy = new double[p.length];
        System.arraycopy(p, 0, copy, 0, p.length);
        return copy;
    }
}
