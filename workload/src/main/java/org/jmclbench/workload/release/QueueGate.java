package org.jmclbench.workload.release;

import java.util.concurrent.locks.LockSupport;

/**
 * What an RTSJ event handler does by default: every event is processed, in release order
 * across both tasks (a ticket order: event k runs after event k - 1 has ended); a job that
 * completes after its deadline is late.
 */
public final class QueueGate extends PolicyGate {
    private volatile int turn;

    @Override
    public boolean admit(int k) {
        return true;
    }

    @Override
    public boolean acquire(int k) {
        while (turn != k) {
            LockSupport.park(); // the handler of k - 1 unparks us when it ends
        }
        return true;
    }

    @Override
    public boolean abortRequested(int k) {
        return false;
    }

    @Override
    public void release(int k) {
        turn = k + 1;
        wakeOtherHandlers();
    }
}
