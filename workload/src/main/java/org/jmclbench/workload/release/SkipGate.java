package org.jmclbench.workload.release;

import java.util.concurrent.atomic.AtomicInteger;

/**
 * The thesis's SkipTest: an event released while a job holds the robot is dropped.
 *
 * <p>The dispatcher takes the robot on the job's behalf at release time, so the robot counts
 * as busy from a job's release to its end, and no two handlers can ever start together.
 */
public final class SkipGate extends PolicyGate {
    private final AtomicInteger owner = new AtomicInteger(FREE);

    @Override
    public boolean admit(int k) {
        return owner.compareAndSet(FREE, k);
    }

    @Override
    public boolean acquire(int k) {
        return true; // taken at admission
    }

    @Override
    public boolean abortRequested(int k) {
        return false;
    }

    @Override
    public void release(int k) {
        owner.set(FREE);
    }
}
