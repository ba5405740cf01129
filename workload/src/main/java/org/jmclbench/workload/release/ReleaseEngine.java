package org.jmclbench.workload.release;

import org.jmclbench.core.record.JobRecords;

/**
 * One real-time replay: a {@link ReleaseDispatcher} and one {@link TaskHandler} per task,
 * started together, run to the last event and joined; every event of the schedule ends up in
 * the records exactly once as done, late, skipped or terminated.
 */
public final class ReleaseEngine {
    /** Handlers are started this long before the release of time 0, so they are parked by then. */
    static final long LEAD_NS = 20_000_000L;
    /** Java priority of the dispatcher thread: above the handlers. */
    public static final int DISPATCHER_PRIORITY = Thread.MAX_PRIORITY;
    /** Java priority of the handler threads. */
    public static final int HANDLER_PRIORITY = Thread.MAX_PRIORITY - 1;
    /** Task names by task index, for thread names. */
    private static final String[] TASK_NAMES = {"predict", "update"};

    private final ReleaseSchedule schedule;
    private final PolicyGate policy;
    private final EventJob job;
    private final JobRecords records;
    private final ThreadCpuClock cpuClock;
    private final long spinNs;
    private long runStartNanoTime;
    private long allocatedBytes = -1;

    public ReleaseEngine(ReleaseSchedule schedule, PolicyGate policy, EventJob job,
                         JobRecords records, ThreadCpuClock cpuClock, long spinNs) {
        if (records.outcome.length < schedule.size()) {
            throw new IllegalArgumentException("records hold " + records.outcome.length
                    + " events, the schedule " + schedule.size());
        }
        this.schedule = schedule;
        this.policy = policy;
        this.job = job;
        this.records = records;
        this.cpuClock = cpuClock;
        this.spinNs = spinNs;
    }

    /**
     * Runs the replay to its end. Times in the records are ns from the release of time 0.
     *
     * @throws IllegalStateException when a job threw or an event was left unaccounted for
     */
    public void run() throws InterruptedException {
        int n = schedule.size();
        for (int k = 0; k < n; k++) {
            records.releaseNs[k] = schedule.releaseNs[k];
            records.deadlineNs[k] = schedule.deadlineNs[k];
        }
        TaskHandler[] handlers = new TaskHandler[TASK_NAMES.length];
        Thread[] handlerThreads = new Thread[handlers.length];
        // Dispatcher above handlers; Linux ignores Java priorities unless the JVM runs with
        // -XX:ThreadPriorityPolicy=1 as root, and SCHED_FIFO comes from chrt on the whole JVM.
        int handlerPriority = HANDLER_PRIORITY;
        for (int t = 0; t < handlers.length; t++) {
            handlers[t] = new TaskHandler(TASK_NAMES[t], schedule.countOf(t), policy, job, records,
                    cpuClock);
            handlerThreads[t] = handlers[t].newThread(handlerPriority);
        }
        policy.handlerThreads(handlerThreads);
        ReleaseDispatcher dispatcher = new ReleaseDispatcher(schedule.releaseNs, schedule.task,
                handlers, policy, records, spinNs);
        Thread dispatcherThread = new Thread(dispatcher, "jmclbench-dispatcher");
        dispatcherThread.setDaemon(true);
        dispatcherThread.setPriority(DISPATCHER_PRIORITY);

        long t0 = System.nanoTime() + LEAD_NS;
        runStartNanoTime = t0;
        dispatcher.runStart(t0);
        for (TaskHandler h : handlers) {
            h.runStart(t0);
        }
        for (Thread t : handlerThreads) {
            t.start();
        }
        dispatcherThread.start();
        dispatcherThread.join();
        for (Thread t : handlerThreads) {
            t.join();
        }
        allocatedBytes = dispatcher.allocatedBytes();
        for (TaskHandler h : handlers) {
            allocatedBytes = allocatedBytes < 0 || h.allocatedBytes() < 0 ? -1 : allocatedBytes + h.allocatedBytes();
        }
        for (TaskHandler h : handlers) {
            if (h.failure() != null) {
                throw new IllegalStateException("a job failed: " + h.failure(), h.failure());
            }
        }
        for (int k = 0; k < n; k++) {
            if (records.outcome[k] == JobRecords.PENDING) {
                throw new IllegalStateException("event " + k + " was never accounted for");
            }
        }
    }

    /**
     * Heap bytes the dispatcher and handler threads allocated during the last {@link #run()},
     * the jobs' own allocation included (zero for an allocation-free job), or -1 where the
     * runtime does not count allocation.
     */
    public long allocatedBytes() {
        return allocatedBytes;
    }

    /** The System.nanoTime of the release of time 0 of the last {@link #run()}. */
    public long runStartNanoTime() {
        return runStartNanoTime;
    }
}
