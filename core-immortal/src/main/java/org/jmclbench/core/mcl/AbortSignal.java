package org.jmclbench.core.mcl;

/**
 * Asks a job in progress to stop: the localizer polls it before each block of
 * {@link MclConfig#pollInterval} particles ({@link MotionModel#ABORT_BLOCK}, 64, unless a
 * verification run makes it smaller) and, when it answers true, abandons the job without
 * changing any state. Implementations must be cheap and allocation-free.
 */
public interface AbortSignal {
    /** True when the job in progress should be abandoned. */
    boolean abortRequested();

    /** A signal that never asks for an abort (ideal runs, skip and queue policies, tests). */
    AbortSignal NEVER = new AbortSignal() {
        @Override
        public boolean abortRequested() {
            return false;
        }
    };
}
