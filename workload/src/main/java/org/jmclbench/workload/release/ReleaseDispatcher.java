package org.jmclbench.workload.release;

import java.util.concurrent.locks.LockSupport;
import org.jmclbench.core.record.JobRecords;

/**
 * The one thread that walks the merged timeline: it sleeps until each event's absolute
 * release time on the monotonic clock, notes when it actually woke, lets the
 * {@link PolicyGate} admit or drop the event, and releases it to its task's handler. Events of
 * the same release time are all decided, in timeline order, before any is released.
 *
 * <p>The wait is cyclictest's: park until the absolute target (re-parking after early
 * returns), optionally park only until {@code spinNs} before it and busy-spin the rest.
 * Nothing in the loop allocates, logs or does I/O.
 */
public final class ReleaseDispatcher implements Runnable {
    private final long[] releaseNs;
    private final int[] task;
    private final TaskHandler[] handlers;
    private final PolicyGate policy;
    private final JobRecords records;
    private final long spinNs;
    private long runStartNs;
    private volatile long allocatedBytes = -1;

    /**
     * @param releaseNs scheduled release of each merged event, ns from the run start,
     *                  non-decreasing
     * @param task      each event's task, an index into {@code handlers}
     */
    public ReleaseDispatcher(long[] releaseNs, int[] task, TaskHandler[] handlers,
                             PolicyGate policy, JobRecords records, long spinNs) {
        this.releaseNs = releaseNs;
        this.task = task;
        this.handlers = handlers;
        this.policy = policy;
        this.records = records;
        this.spinNs = spinNs;
    }

    /** The absolute System.nanoTime of the release of time 0; set before the thread starts. */
    void runStart(long nanoTime) {
        this.runStartNs = nanoTime;
    }

    /** Heap bytes this thread allocated in its release loop, or -1 where unknown. */
    long allocatedBytes() {
        return allocatedBytes;
    }

    @Override
    public void run() {
        long allocated0 = ThreadAllocation.now();
        try {
            releaseAll();
        } finally {
            allocatedBytes = ThreadAllocation.since(allocated0);
        }
    }

    private void releaseAll() {
        final long t0 = runStartNs;
        final JobRecords r = records;
        try {
            int k = 0;
            while (k < releaseNs.length) {
                long wake = sleepUntil(t0 + releaseNs[k], spinNs);
                // Events of one release instant: the policy decides each, in timeline order, before
                // any reaches its handler, so none of them has started when the next is decided
                // (RELEASE-ENGINE.md, "Events at the same time").
                int end = k + 1;
                while (end < releaseNs.length && releaseNs[end] == releaseNs[k]) {
                    end++;
                }
                for (int j = k; j < end; j++) {
                    r.wakeNs[j] = wake - t0;
                    if (!policy.admit(j)) {
                        r.outcome[j] = JobRecords.SKIPPED;
                    }
                    int aborted = policy.superseded();
                    if (aborted >= 0) {
                        r.requestAbort(aborted, wake - t0); // the request is the admit just made
                    }
                }
                for (int j = k; j < end; j++) {
                    if (r.outcome[j] != JobRecords.SKIPPED) {
                        handlers[task[j]].release(j);
                    }
                }
                k = end;
            }
        } finally {
            for (TaskHandler h : handlers) {
                h.stop();
            }
        }
    }

    /**
     * Waits until System.nanoTime() reaches {@code target}: parks (to {@code spinNs} before
     * it, when non-zero), then spins. Returns the time read at wake-up.
     */
    static long sleepUntil(long target, long spinNs) {
        long parkUntil = target - spinNs;
        long now = System.nanoTime();
        while (now < parkUntil) {
            LockSupport.parkNanos(parkUntil - now);
            now = System.nanoTime();
        }
        while (now < target) {
            now = System.nanoTime();
        }
        return now;
    }
}
