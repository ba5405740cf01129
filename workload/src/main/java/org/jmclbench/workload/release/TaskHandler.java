package org.jmclbench.workload.release;

import java.util.concurrent.locks.LockSupport;
import org.jmclbench.core.mcl.AbortSignal;
import org.jmclbench.core.record.JobRecords;

/**
 * The dedicated thread of one task (predict or update), like RTSJ's BoundAsyncEventHandler:
 * it takes the events the dispatcher released to it, in order, runs their jobs on the robot
 * under the run's {@link PolicyGate}, and records each job's times and outcome ({@link JobRecorder}).
 *
 * <p>The release queue is a preallocated single-producer (dispatcher), single-consumer
 * (this thread) ring large enough for every event of the task, so it never fills and never
 * allocates; an empty queue parks the thread until the dispatcher unparks it.
 */
public final class TaskHandler implements Runnable {
    private static final int STOP = -1;

    private final String name;
    private final PolicyGate policy;
    private final EventJob job;
    private final JobRecorder recorder;
    private final int[] queue;
    private final JobAbortSignal abortSignal = new JobAbortSignal();
    private volatile long head; // next slot to take (written by this thread)
    private volatile long tail; // next slot to fill (written by the dispatcher)
    private Thread thread;
    private volatile Throwable failure;
    private volatile long allocatedBytes = -1;

    /**
     * @param capacity the number of events of this task in the replay (the queue's size
     *                 beyond that is for the stop mark)
     */
    public TaskHandler(String name, int capacity, PolicyGate policy, EventJob job,
                       JobRecords records, ThreadCpuClock cpuClock) {
        this.name = name;
        this.policy = policy;
        this.job = job;
        this.recorder = new JobRecorder(records, cpuClock, 0);
        this.queue = new int[capacity + 1];
    }

    /** Creates (not starts) this handler's thread at the given Java priority. */
    Thread newThread(int priority) {
        thread = new Thread(this, "jmclbench-" + name + "-handler");
        thread.setDaemon(true);
        thread.setPriority(priority);
        return thread;
    }

    /** The absolute System.nanoTime of the release of time 0; set before the thread starts. */
    void runStart(long nanoTime) {
        recorder.runStart(nanoTime);
    }

    /** The first exception a job threw, or null. */
    Throwable failure() {
        return failure;
    }

    /** Dispatcher side: releases merged event k to this task. */
    void release(int k) {
        offer(k);
    }

    /** Dispatcher side: no more events; the thread ends once its queue is drained. */
    void stop() {
        offer(STOP);
    }

    private void offer(int k) {
        long t = tail;
        queue[(int) (t % queue.length)] = k;
        tail = t + 1; // volatile write publishes the slot
        LockSupport.unpark(thread);
    }

    private int take() {
        long h = head;
        while (tail == h) {
            LockSupport.park();
        }
        int k = queue[(int) (h % queue.length)];
        head = h + 1;
        return k;
    }

    /** Heap bytes this thread allocated while handling jobs (the job's own included), or -1. */
    long allocatedBytes() {
        return allocatedBytes;
    }

    @Override
    public void run() {
        long allocated0 = ThreadAllocation.now();
        handle();
        allocatedBytes = ThreadAllocation.since(allocated0);
    }

    private void handle() {
        final JobRecorder recorder = this.recorder;
        while (true) {
            int k = take();
            if (k == STOP) {
                return;
            }
            if (!policy.acquire(k)) {
                recorder.recordNeverStarted(k); // superseded before it could start
                continue;
            }
            abortSignal.begin(k);
            recorder.start();
            boolean completed;
            try {
                completed = job.run(k, abortSignal);
            } catch (Throwable e) {
                // A broken job must not hang the run: free the robot, keep draining, and
                // leave k pending so that the engine reports the run as failed.
                if (failure == null) {
                    failure = e;
                }
                policy.release(k);
                continue;
            }
            recorder.end();
            policy.release(k); // before the CPU clock's second read: the next job need not wait for it
            recorder.record(k, completed, abortSignal.seenNs);
        }
    }

    /** The abort request of the job in progress, as the MCL loops poll it; remembers when a poll first saw it. */
    private final class JobAbortSignal implements AbortSignal {
        private int event;
        /** System.nanoTime of the first poll that answered true in this job, or -1. */
        long seenNs = -1;

        void begin(int k) {
            event = k;
            seenNs = -1;
        }

        @Override
        public boolean abortRequested() {
            if (!policy.abortRequested(event)) {
                return false;
            }
            if (seenNs < 0) {
                seenNs = System.nanoTime();
            }
            return true;
        }
    }
}
