package org.jmclbench.verification.seeded.bound;

import javax.realtime.AsynchronouslyInterruptedException;

import org.jmclbench.core.mcl.AbortSignal;
import org.jmclbench.rtsjcompat.Atc;

/**
 * An RTSJ job in two designs, as the rtsj engine's (AbortBoundTest): its AI-enabled entry hands
 * the job a signal whose polls are delivery points (DELIVERED), or runs the job in a synchronized
 * block with a signal that has none (DEFERRED: the AIE waits for the whole job).
 */
public final class AtcJob {
    /** How the job meets an AIE. */
    public enum Design { DEFERRED, DELIVERED }

    private final Design design;
    private final Object robot = new Object();
    private final double[] x = new double[256];

    public AtcJob(Design design) {
        this.design = design;
    }

    /** The AI-enabled part, with delivery points as the weaver puts them (entry, after the call). */
    public void run(AsynchronouslyInterruptedException interrupt) throws AsynchronouslyInterruptedException {
        Atc.poll();
        job(design == Design.DELIVERED ? Points.INSTANCE : AbortSignal.NEVER);
        Atc.poll();
    }

    private void job(AbortSignal signal) {
        if (design == Design.DEFERRED) {
            synchronized (robot) {
                loop(signal);
            }
        } else {
            loop(signal);
        }
    }

    private void loop(AbortSignal signal) {
        for (int i = 0; i < x.length; i++) {
            if ((i & 63) == 0 && signal.abortRequested()) {
                return;
            }
            x[i] += 1;
        }
    }

    /** A signal whose every poll is a delivery point. */
    static final class Points implements AbortSignal {
        static final Points INSTANCE = new Points();

        @Override
        public boolean abortRequested() {
            try {
                Atc.poll();
            } catch (AsynchronouslyInterruptedException e) {
                throw new IllegalStateException(e);
            }
            return false;
        }
    }
}
