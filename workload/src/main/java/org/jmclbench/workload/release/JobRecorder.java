package org.jmclbench.workload.release;

import org.jmclbench.core.record.JobRecords;
import org.jmclbench.workload.shim.CpuClock;

/**
 * How a thread records its jobs into the run's {@link JobRecords}: the start and end times
 * (System.nanoTime, stored as ns from the run start), the thread's CPU time over the job, and
 * the outcome. One per thread that runs jobs (each handler of a real-time run, the rtsj engine's
 * tasks, the ideal run's thread); {@code bench/record-cost.sh} measures exactly this code.
 * Allocation-free.
 *
 * <p>Per job: {@link #start()} just before the job, {@link #end()} just after it, then, once the
 * robot has been handed on, {@link #record}. The CPU clock is read in {@code start} and in
 * {@code record}: on a virtual machine it is a system call (about a microsecond), and the second
 * read would otherwise keep the next job waiting for the robot. The CPU time so includes the
 * two time stamps and the robot's hand-over, which no preemption inflates (the clock counts
 * only this thread's time on a CPU). With a clock that is not {@link ThreadCpuClock#usable()}
 * ({@code --no-cpu-time}) neither read happens and the CPU time is -1.
 *
 * <p>A thread with a clock of its own, the rtsj engine's tasks (RTSJ's real-time clock, which Java
 * PathFinder runs on virtual time), gives the times instead: {@link #runStart(long)} on that
 * clock, {@link #startCpu()} where the CPU time is to begin, {@link #started(long)} and
 * {@link #ended(long)} around the job, then {@link #record} as above.
 */
public final class JobRecorder {
    private final JobRecords records;
    private final CpuClock cpuClock;
    private long runStartNs;
    private long cpuStart;
    private long startNs;
    private long endNs;

    /**
     * @param runStartNs the System.nanoTime of the run's time 0 (may be set later with
     *                   {@link #runStart(long)})
     */
    public JobRecorder(JobRecords records, CpuClock cpuClock, long runStartNs) {
        this.records = records;
        this.cpuClock = cpuClock;
        this.runStartNs = runStartNs;
    }

    /** Sets the System.nanoTime of the run's time 0, before the first job. */
    public void runStart(long nanoTime) {
        this.runStartNs = nanoTime;
    }

    /** Just before the job: the CPU clock, then the start time. */
    public void start() {
        cpuStart = cpuClock.now();
        startNs = System.nanoTime();
    }

    /** Just after the job, before anything else: the end time. */
    public void end() {
        endNs = System.nanoTime();
    }

    /** Where the job's CPU time begins, its start taken later ({@link #started(long)}): the CPU clock. */
    public void startCpu() {
        cpuStart = cpuClock.now();
    }

    /** The job started at {@code at}, on the clock of {@link #runStart(long)}. */
    public void started(long at) {
        startNs = at;
    }

    /** The job ended at {@code at}, on the clock of {@link #runStart(long)}. */
    public void ended(long at) {
        endNs = at;
    }

    /**
     * After the job's {@link #end()} (and the robot's release): stores event k's start, end, CPU
     * time and outcome, terminated unless it completed, else done by its deadline (or with no
     * deadline, -1) or late.
     *
     * @param seenNanoTime when the job saw its abort request (System.nanoTime, or the clock of
     *                     {@link #started(long)}), or -1
     */
    public void record(int k, boolean completed, long seenNanoTime) {
        long cpuEnd = cpuClock.now();
        JobRecords r = records;
        long t0 = runStartNs;
        long end = endNs - t0;
        r.startNs[k] = startNs - t0;
        r.endNs[k] = end;
        r.cpuNs[k] = cpuStart < 0 ? -1 : cpuEnd - cpuStart;
        if (seenNanoTime >= 0) {
            r.abortSeen(k, seenNanoTime - t0);
        }
        if (!completed) {
            r.outcome[k] = JobRecords.TERMINATED;
        } else {
            long deadline = r.deadlineNs[k];
            r.outcome[k] = deadline < 0 || end <= deadline ? JobRecords.DONE : JobRecords.LATE;
        }
    }

    /** Event k's job never started (superseded before it could): terminated, with no times and no CPU time. */
    public void recordNeverStarted(int k) {
        JobRecords r = records;
        r.startNs[k] = -1;
        r.endNs[k] = -1;
        r.cpuNs[k] = -1;
        r.outcome[k] = JobRecords.TERMINATED;
    }
}
