package org.jmclbench.verification.seeded.mission;

import org.jmclbench.scj.JobGate;
import org.jmclbench.scj.MissionConfiguration;
import org.jmclbench.core.policy.OverrunPolicy;
import org.jmclbench.verification.mission.MissionFault;

/**
 * Seeded P2 bug: an unguarded read. The gate counts admissions under its lock, and a job's abort
 * poll compares that count without the lock (a terminate policy built on a plain counter instead
 * of the volatile latest event): a data race between a release and a running job.
 */
public final class UnguardedRead implements MissionFault {

    @Override
    public JobGate gate(MissionConfiguration configuration, int events) {
        return new CountingGate(configuration.policy, events);
    }

    /** Written under the lock, read without it. */
    public static final class CountingGate extends JobGate {
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
