package org.jmclbench.workload.release;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.concurrent.TimeUnit;
import org.jmclbench.core.policy.OverrunPolicy;
import org.jmclbench.core.timeline.Timeline;
import org.jmclbench.core.mcl.AbortSignal;
import org.jmclbench.core.record.JobRecords;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * The engine's policies on synthetic timelines with a job of controlled cost. Margins are wide:
 * the machine is shared and noisy, so only gross behaviour is asserted (an overloaded run must
 * overrun, a light one must nearly never miss), never timings.
 */
@Timeout(value = 30, unit = TimeUnit.SECONDS)
class ReleaseEngineTest {
    private static final long MS = 1_000_000L;

    /** A job that busy-spins for a fixed time, polling the abort request every ~20 us. */
    static final class SpinJob implements EventJob {
        final long costNs;
        int started;
        int completed;
        int aborted;
        volatile int running;
        volatile boolean overlapSeen;

        SpinJob(long costNs) {
            this.costNs = costNs;
        }

        @Override
        public boolean run(int k, AbortSignal abort) {
            if (running++ != 0) {
                overlapSeen = true;
            }
            started++;
            try {
                long end = System.nanoTime() + costNs;
                while (System.nanoTime() < end) {
                    long poll = System.nanoTime() + 20_000;
                    while (System.nanoTime() < poll) {
                        // spin
                    }
                    if (abort.abortRequested()) {
                        aborted++;
                        return false;
                    }
                }
                completed++;
                return true;
            } finally {
                running--;
            }
        }
    }

    /** n events every periodNs, every third one an update (both handlers take part). */
    static Timeline periodicTimeline(int n, long periodNs) {
        double[] odo = new double[n - n / 3];
        double[] laser = new double[n / 3];
        int i = 0;
        int j = 0;
        for (int k = 0; k < n; k++) {
            if (k % 3 == 2) {
                laser[j++] = k * periodNs / 1e9;
            } else {
                odo[i++] = k * periodNs / 1e9;
            }
        }
        return Timeline.merge(odo, laser);
    }

    /** The timeline's releases, each due one period after it. */
    static ReleaseSchedule periodicSchedule(Timeline t, long periodNs) {
        int n = t.size();
        long[] release = new long[n];
        long[] deadline = new long[n];
        int[] task = new int[n];
        for (int k = 0; k < n; k++) {
            release[k] = Math.round(t.time(k) * 1e9);
            deadline[k] = release[k] + periodNs;
            task[k] = t.task(k);
        }
        return ReleaseSchedule.of(release, deadline, task);
    }

    static JobRecords run(String policy, int n, long periodNs, EventJob job) throws Exception {
        Timeline t = periodicTimeline(n, periodNs);
        JobRecords records = new JobRecords(t, false);
        new ReleaseEngine(periodicSchedule(t, periodNs), PolicyGate.of(OverrunPolicy.ofLabel(policy)), job, records,
                ThreadCpuClock.probe(), 0).run();
        assertAccountedOnce(records, n);
        return records;
    }

    static JobRecords run(String policy, int n, long periodNs, SpinJob job) throws Exception {
        JobRecords records = run(policy, n, periodNs, (EventJob) job);
        assertTrue(!job.overlapSeen, "two jobs ran on the robot at once");
        return records;
    }

    static int count(JobRecords r, byte outcome) {
        int c = 0;
        for (byte o : r.outcome) {
            c += o == outcome ? 1 : 0;
        }
        return c;
    }

    /** Every event exactly one final outcome, with times consistent with it. */
    static void assertAccountedOnce(JobRecords r, int n) {
        for (int k = 0; k < n; k++) {
            byte o = r.outcome[k];
            assertNotEquals(JobRecords.PENDING, o, "event " + k + " pending");
            assertTrue(r.wakeNs[k] >= r.releaseNs[k], "event " + k + " woke before its release");
            if (o == JobRecords.DONE || o == JobRecords.LATE) {
                assertTrue(r.startNs[k] >= r.wakeNs[k] && r.endNs[k] >= r.startNs[k], "event " + k);
                assertEquals(o == JobRecords.LATE, r.endNs[k] > r.deadlineNs[k], "event " + k);
            } else if (o == JobRecords.SKIPPED) {
                assertEquals(-1, r.startNs[k]);
                assertEquals(-1, r.endNs[k]);
            } else {
                assertEquals(JobRecords.TERMINATED, o);
            }
        }
        // the robot is one resource: started jobs never overlap, and run in release order
        long lastEnd = -1;
        for (int k = 0; k < n; k++) {
            if (r.startNs[k] >= 0) {
                assertTrue(r.startNs[k] >= lastEnd, "event " + k + " started before the previous job ended");
                lastEnd = r.endNs[k];
            }
        }
    }

    @Test
    void overloadedSkipDropsEventsReleasedWhileBusy() throws Exception {
        SpinJob job = new SpinJob(30 * MS);
        JobRecords r = run("skip", 20, 10 * MS, job);
        assertTrue(count(r, JobRecords.SKIPPED) >= 5, "skipped " + count(r, JobRecords.SKIPPED));
        assertEquals(0, count(r, JobRecords.TERMINATED));
        assertEquals(0, job.aborted);
        assertEquals(20, count(r, JobRecords.SKIPPED) + job.completed);
    }

    @Test
    void overloadedTerminateAbortsTheRunningJob() throws Exception {
        SpinJob job = new SpinJob(30 * MS);
        JobRecords r = run("terminate", 20, 10 * MS, job);
        assertTrue(job.aborted >= 5, "aborted " + job.aborted);
        assertEquals(0, count(r, JobRecords.SKIPPED));
        for (int k = 0; k < 20; k++) {
            if (r.outcome[k] == JobRecords.TERMINATED && r.abortFromNs(k) >= 0) {
                long seen = r.abortSeenFromNs(k);
                assertTrue(seen >= r.abortFromNs(k) && seen <= r.endNs[k], "job " + k + " saw its abort between request and end: " + seen);
            }
        }
        assertEquals(20, count(r, JobRecords.TERMINATED) + job.completed);
        // nothing supersedes the last event: it always completes
        assertTrue(r.outcome[19] == JobRecords.DONE || r.outcome[19] == JobRecords.LATE);
    }

    @Test
    void overloadedQueueCompletesEveryJobLate() throws Exception {
        SpinJob job = new SpinJob(30 * MS);
        JobRecords r = run("queue", 20, 10 * MS, job);
        assertEquals(20, job.completed);
        assertEquals(0, count(r, JobRecords.SKIPPED) + count(r, JobRecords.TERMINATED));
        assertTrue(count(r, JobRecords.LATE) >= 10, "late " + count(r, JobRecords.LATE));
    }

    @Test
    void lightLoadNearlyNeverMisses() throws Exception {
        for (String policy : new String[] {"skip", "terminate", "queue"}) {
            SpinJob job = new SpinJob(MS / 10);
            JobRecords r = run(policy, 20, 20 * MS, job);
            int misses = 20 - count(r, JobRecords.DONE);
            // wide margin: a loaded 2-core VM can delay a few releases; overload misses 10 or more
            assertTrue(misses <= 8, policy + ": " + misses + " of 20 missed");
        }
    }

    @Test
    void cpuTimeIsRecordedWhenTheRuntimeTellsIt() throws Exception {
        ThreadCpuClock clock = ThreadCpuClock.probe();
        SpinJob job = new SpinJob(2 * MS);
        JobRecords r = run("skip", 6, 10 * MS, job);
        for (int k = 0; k < 6; k++) {
            if (r.outcome[k] == JobRecords.DONE || r.outcome[k] == JobRecords.LATE) {
                if (clock.usable()) {
                    assertTrue(r.cpuNs[k] > 0, clock.status());
                } else {
                    assertEquals(-1, r.cpuNs[k]);
                }
            }
        }
    }

    /**
     * The dispatcher and handlers allocate nothing per event: 400 empty jobs (after a warm-up
     * replay) allocate less than one 16-byte object per 25 events on the engine's threads.
     */
    @Test
    void theReleasePathAllocatesNothing() throws Exception {
        EventJob empty = (k, abort) -> true;
        long allocated = -1;
        for (int round = 0; round < 2; round++) {
            Timeline t = periodicTimeline(400, MS);
            JobRecords records = new JobRecords(t, false);
            ReleaseEngine engine = new ReleaseEngine(periodicSchedule(t, MS), PolicyGate.of(OverrunPolicy.ofLabel("queue")),
                    empty, records, ThreadCpuClock.probe(), 0);
            engine.run();
            allocated = engine.allocatedBytes();
        }
        if (ThreadAllocation.now() >= 0) { // the runtime counts allocation (HotSpot, OpenJ9)
            assertTrue(allocated >= 0 && allocated < 256, "the engine allocated " + allocated + " bytes for 400 events");
        }
    }
}
