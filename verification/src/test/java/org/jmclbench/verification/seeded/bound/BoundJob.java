package org.jmclbench.verification.seeded.bound;

import org.jmclbench.core.mcl.AbortSignal;

/** Cooperative jobs whose bounds the abort-bound analysis must find (AbortBoundTest). */
public final class BoundJob {
    private final double[] x = new double[256];

    /** Polls every 16 particles, then every 32: the longest gap is 32 steps, in the second loop. */
    public boolean run(AbortSignal abort) {
        for (int i = 0; i < x.length; i++) {
            if ((i & 15) == 0 && abort.abortRequested()) {
                return false;
            }
            x[i] += 1;
        }
        for (int i = 0; i < x.length; i++) {
            if ((i & 31) == 0 && abort.abortRequested()) {
                return false;
            }
            x[i] *= 2;
        }
        return true;
    }

    /** Seeded: the normalisation after a polling loop does not poll, so after a request it runs whole. */
    public boolean unpolledTail(AbortSignal abort) {
        double total = 0;
        for (int i = 0; i < x.length; i++) {
            if ((i & 63) == 0 && abort.abortRequested()) {
                return false;
            }
            total += x[i];
        }
        for (int i = 0; i < x.length; i++) { // SEEDED: no abort point
            x[i] /= total;
        }
        return true;
    }
}
