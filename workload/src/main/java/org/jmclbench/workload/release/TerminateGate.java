package org.jmclbench.workload.release;

import java.util.concurrent.atomic.AtomicInteger;

/**
 * The thesis's TermTest: a release aborts the job in progress and the new event is processed.
 *
 * <p>Only the most recently released event may run: a job is asked to abort as soon as a later
 * event is released (the abort is cooperative, polled by the MCL loops every poll interval, 64
 * particles by default), and an event superseded while it still waited for the robot never
 * starts (terminated).
 */
public final class TerminateGate extends PolicyGate {
    private final AtomicInteger owner = new AtomicInteger(FREE);
    private volatile int latest = FREE;
    // the event the last admit superseded; dispatcher thread only
    private int superseded = FREE;

    @Override
    public boolean admit(int k) {
        superseded = latest;
        latest = k; // the running job sees this through abortRequested and stops
        return true;
    }

    @Override
    public int superseded() {
        return superseded;
    }

    @Override
    public boolean acquire(int k) {
        while (true) {
            if (latest != k) {
                return false;
            }
            if (owner.compareAndSet(FREE, k)) {
                return true;
            }
            // The aborted job is still unwinding; its release unparks us.
            java.util.concurrent.locks.LockSupport.park();
        }
    }

    @Override
    public boolean abortRequested(int k) {
        return latest != k;
    }

    @Override
    public void release(int k) {
        owner.set(FREE);
        wakeOtherHandlers();
    }
}
