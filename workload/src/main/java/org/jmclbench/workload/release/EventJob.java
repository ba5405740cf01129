package org.jmclbench.workload.release;

import org.jmclbench.core.mcl.AbortSignal;

/** The work of one released event: a job of its task on the shared robot. */
public interface EventJob {
    /**
     * Runs the job of merged event k and, when it completes, commits its results (the
     * estimate) into the run's records. Must not allocate, block or do I/O.
     *
     * @return true when the job completed, false when it stopped on {@code abort} and left
     *         the robot state exactly as it was
     */
    boolean run(int k, AbortSignal abort);
}
