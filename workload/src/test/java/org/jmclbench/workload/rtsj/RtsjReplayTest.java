package org.jmclbench.workload.rtsj;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.util.concurrent.atomic.AtomicInteger;

import org.jmclbench.core.mcl.AbortSignal;
import org.jmclbench.core.policy.OverrunPolicy;
import org.jmclbench.core.record.JobRecords;
import org.jmclbench.core.timeline.Timeline;
import org.jmclbench.workload.release.EventJob;
import org.jmclbench.workload.release.ReleaseSchedule;
import org.jmclbench.workload.release.ThreadCpuClock;
import org.jmclbench.workload.shim.CpuClock;
import org.junit.jupiter.api.Test;

/**
 * The rtsj engine's asynchronous transfer of control on the woven classes: a long predict job
 * (polling its abort signal as the MCL loops do) is overtaken by an update release 50 ms later.
 * Under terminate, design atomic throws the AIE at the job's next poll, before its commit; design
 * thesis defers it until the job has run to its end. Times are generous: this is a 2-core VM. A
 * replay whose first job did not start before the second release (a loaded machine) tests
 * nothing about ATC and is run again ({@link #firstJobStarted}).
 */
class RtsjReplayTest {
    private static final long JOB_NS = 400_000_000L;
    private static final long SECOND_RELEASE_NS = 50_000_000L;

    /** Job 0 runs 400 ms polling every 0.1 ms; job 1 returns at once. Counts commits. */
    private static final class LongFirstJob implements EventJob {
        final AtomicInteger commits = new AtomicInteger();

        @Override
        public boolean run(int k, AbortSignal abort) {
            if (k == 0) {
                long end = System.nanoTime() + JOB_NS;
                long nextPoll = 0;
                while (System.nanoTime() < end) {
                    if (System.nanoTime() >= nextPoll) {
                        if (abort.abortRequested()) {
                            return false;
                        }
                        nextPoll = System.nanoTime() + 100_000L;
                    }
                }
            }
            commits.incrementAndGet();
            return true;
        }
    }

    private static RtsjReplay replay(RtsjDesign design, OverrunPolicy policy, EventJob job, JobRecords records) {
        return new RtsjReplay(schedule(), policy, design, job, records);
    }

    private static ReleaseSchedule schedule() {
        return ReleaseSchedule.of(new long[] {0, SECOND_RELEASE_NS},
                new long[] {10_000_000_000L, 10_000_000_000L}, new int[] {Timeline.PREDICT, Timeline.UPDATE});
    }

    /**
     * Computes on the thread's CPU clock: job 0 until it has used {@link #JOB_NS} of CPU or is
     * aborted at a poll (every 0.1 ms of CPU; the atomic design's AIE is thrown there), noting
     * before each poll the CPU it has used; job 1 uses {@link #SECOND_CPU_NS}.
     */
    private static final class CpuJob implements EventJob {
        static final long SECOND_CPU_NS = 20_000_000L;
        final CpuClock clock;
        /** Job 0's CPU time at its latest poll, or -1. */
        volatile long usedAtPoll = -1;

        CpuJob(CpuClock clock) {
            this.clock = clock;
        }

        @Override
        public boolean run(int k, AbortSignal abort) {
            long begin = clock.now();
            long end = begin + (k == 0 ? JOB_NS : SECOND_CPU_NS);
            long nextPoll = 0;
            for (long now = begin; now < end; now = clock.now()) {
                if (k == 0 && now >= nextPoll) {
                    usedAtPoll = now - begin;
                    if (abort.abortRequested()) {
                        return false;
                    }
                    nextPoll = now + 100_000L;
                }
            }
            return true;
        }
    }

    /** The job and the records of one terminate replay. */
    private static final class Attempt {
        final LongFirstJob job = new LongFirstJob();
        final JobRecords records = records();
    }

    /** A terminate replay in which the first job started before the second release (at most five tries). */
    private static Attempt firstJobStarted(RtsjDesign design) throws Exception {
        for (int attempt = 0; ; attempt++) {
            Attempt a = new Attempt();
            replay(design, OverrunPolicy.TERMINATE, a.job, a.records).run(60_000_000_000L);
            long start = a.records.startNs[0];
            if (start >= 0 && start < SECOND_RELEASE_NS || attempt == 4) {
                return a;
            }
        }
    }

    private static JobRecords records() {
        return new JobRecords(Timeline.merge(new double[] {0.0}, new double[] {0.05}), false);
    }

    @Test
    void atomicDeliversTheAieAtTheNextPollBeforeTheCommit() throws Exception {
        Attempt a = firstJobStarted(RtsjDesign.ATOMIC);
        JobRecords r = a.records;
        assertEquals(JobRecords.TERMINATED, r.outcome[0]);
        assertEquals(JobRecords.DONE, r.outcome[1]);
        assertEquals(1, a.job.commits.get(), "only the second job committed");
        assertEquals(-1, r.abortFromNs(1), "nothing asked the last job to abort");
        assertTrue(r.abortFromNs(0) >= 0, "an AIE was fired at the first job");
        long latency = r.endNs[0] - r.abortFromNs(0);
        assertTrue(latency < JOB_NS / 2, "aborted at a poll, not at the job's end: " + latency + " ns");
        long seen = r.abortSeenFromNs(0);
        assertTrue(seen >= r.abortFromNs(0) && seen <= r.endNs[0], "the delivery point that threw is recorded: seen "
                + r.abortSeenNs[0] + " ns, abort requested " + r.abortNs[0] + ", job " + r.startNs[0] + " to " + r.endNs[0]);
        assertEquals(-1, r.abortSeenFromNs(1));
    }

    @Test
    void thesisDefersTheAieUntilTheJobHasRunToItsEnd() throws Exception {
        Attempt a = firstJobStarted(RtsjDesign.THESIS);
        JobRecords r = a.records;
        assertNotEquals(JobRecords.TERMINATED, r.outcome[0], "the robot's monitor defers the AIE");
        assertEquals(2, a.job.commits.get());
        assertTrue(r.abortFromNs(0) >= 0, "an AIE was fired at the first job");
        // The abort took the job's remaining time: from the fire, the job ran on to the end of its
        // 400 ms (not timed against the release: a late dispatcher fires later, leaving less).
        assertTrue(r.endNs[0] - r.startNs[0] >= JOB_NS, "the job ran whole: " + (r.endNs[0] - r.startNs[0]) + " ns");
        assertTrue(r.abortFromNs(0) < r.startNs[0] + JOB_NS, "fired while it ran");
        assertEquals(-1, r.abortSeenNs[0], "no delivery point in the job: it never saw the AIE");
    }

    /**
     * On a JVM the shim's CPU clock gives each job its CPU time: at least what a completed job
     * computed, and for a job the AIE cut short at least what it had computed when it saw the
     * abort (the number runs on to the AIE's unwinding). A lower bound only: the CPU clock, not
     * the wall clock, paces the jobs, so a loaded machine cannot make this fail.
     */
    @Test
    void aJobsCpuTimeCoversWhatItComputedAndAnAbortedOnesWhatItComputedUntilTheAbort() throws Exception {
        ThreadCpuClock clock = ThreadCpuClock.probe();
        assumeTrue(clock.usable(), "this JVM has no usable thread CPU clock: " + clock.status());
        for (int attempt = 0; ; attempt++) {
            CpuJob job = new CpuJob(clock);
            JobRecords r = records();
            new RtsjReplay(schedule(), OverrunPolicy.TERMINATE, RtsjDesign.ATOMIC, job, r, clock).run(60_000_000_000L);
            if (r.startNs[0] < 0 && attempt < 4) {
                continue; // superseded before it started (a loaded machine): nothing was aborted
            }
            assertEquals(JobRecords.TERMINATED, r.outcome[0]);
            assertTrue(job.usedAtPoll >= 0, "the first job polled");
            assertTrue(r.cpuNs[0] >= job.usedAtPoll, "the aborted job's CPU time " + r.cpuNs[0]
                    + " ns covers what it computed until the poll the AIE took, " + job.usedAtPoll + " ns");
            assertEquals(JobRecords.DONE, r.outcome[1]);
            assertTrue(r.cpuNs[1] >= CpuJob.SECOND_CPU_NS, "the completed job's CPU time " + r.cpuNs[1]
                    + " ns covers its " + CpuJob.SECOND_CPU_NS + " ns of computing");
            return;
        }
    }

    @Test
    void skipDropsTheReleaseWhileTheRobotIsBusyAndQueueRunsIt() throws Exception {
        for (RtsjDesign design : RtsjDesign.values()) {
            LongFirstJob job = new LongFirstJob();
            JobRecords r = records();
            replay(design, OverrunPolicy.SKIP, job, r).run(60_000_000_000L);
            assertEquals(JobRecords.DONE, r.outcome[0], design.label);
            assertEquals(JobRecords.SKIPPED, r.outcome[1], design.label);
            job = new LongFirstJob();
            r = records();
            replay(design, OverrunPolicy.QUEUE, job, r).run(60_000_000_000L);
            assertEquals(JobRecords.DONE, r.outcome[0], design.label);
            assertEquals(JobRecords.DONE, r.outcome[1], design.label);
            assertTrue(r.startNs[1] >= r.endNs[0], "queue: the update waited for the robot");
            assertEquals(-1, r.cpuNs[0], "a replay given no CPU clock (Java PathFinder's) records no CPU time");
        }
    }
}
