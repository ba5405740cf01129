package org.jmclbench.verification.seeded.mission;

import org.jmclbench.core.mcl.MclConfig;
import org.jmclbench.core.policy.OverrunPolicy;
import org.jmclbench.scj.JobGate;
import org.jmclbench.verification.mission.CheckedConfiguration;

/**
 * Seeded P2 bug in the real mission: an unguarded read. The gate counts admissions under its
 * lock, and a job's abort poll compares that count without the lock (a terminate policy built
 * on a plain counter instead of the volatile latest event): a data race between a release and
 * a running job.
 */
public final class UnguardedReadConfiguration extends CheckedConfiguration {

    public UnguardedReadConfiguration(MclConfig mcl, OverrunPolicy policy, double timeScale) {
        super(mcl, policy, timeScale);
    }

    @Override
    public JobGate newGate(int events) {
        return new CountingGate(policy, events);
    }

    /** Written under the lock, read without it. */
    static final class CountingGate extends JobGate {
        private int admitted;
        private final int events;

        CountingGate(OverrunPolicy policy, int events) {
            super(policy, events);
            this.events = events;
        }

        @Override
        public synchronized boolean admit(int k) {
            admitted++;
            return super.admit(k);
        }

        @Override
        public boolean abortRequested(int k) {
            return admitted > events || super.abortRequested(k);
        }
    }
}
