package org.jmclbench.workload.release;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.jmclbench.core.record.JobRecords;
import org.jmclbench.core.timeline.Timeline;
import org.junit.jupiter.api.Test;

/** What one job's recording stores: times from the run start, the CPU time (or -1) and the outcome. */
class JobRecorderTest {
    private static JobRecords records() {
        return new JobRecords(Timeline.merge(new double[] {0, 1, 2, 3}, new double[0]), false);
    }

    /** Computes until this thread has used cpuNs of CPU (at once without a clock). */
    private static void spin(ThreadCpuClock clock, long cpuNs) {
        long end = clock.now() + cpuNs;
        while (clock.usable() && clock.now() < end) {
            continue;
        }
    }

    @Test
    void outcomesFollowCompletionAndDeadline() {
        JobRecords r = records();
        long t0 = System.nanoTime();
        JobRecorder rec = new JobRecorder(r, ThreadCpuClock.disabled("test"), t0);
        r.deadlineNs[0] = Long.MAX_VALUE;
        r.deadlineNs[1] = 0; // already past at its end
        r.deadlineNs[2] = Long.MAX_VALUE;
        // event 3 keeps the cleared deadline, -1: an ideal run's job, done
        boolean[] completed = {true, true, false, true};
        for (int k = 0; k < 4; k++) {
            rec.start();
            rec.end();
            rec.record(k, completed[k], k == 2 ? t0 + 5 : -1);
        }
        assertEquals(JobRecords.DONE, r.outcome[0]);
        assertEquals(JobRecords.LATE, r.outcome[1]);
        assertEquals(JobRecords.TERMINATED, r.outcome[2]);
        assertEquals(JobRecords.DONE, r.outcome[3]);
        assertEquals(5, r.abortSeenNs[2]);
        assertEquals(-1, r.abortSeenNs[0]);
        for (int k = 0; k < 4; k++) {
            assertTrue(r.startNs[k] >= 0 && r.endNs[k] >= r.startNs[k], "event " + k);
            assertEquals(-1, r.cpuNs[k], "no CPU clock: -1");
        }
    }

    @Test
    void theCpuTimeSpansTheJobWhenTheClockIsUsed() {
        ThreadCpuClock clock = ThreadCpuClock.probe();
        JobRecords r = records();
        JobRecorder rec = new JobRecorder(r, clock, System.nanoTime());
        rec.start();
        spin(clock, 3_000_000);
        rec.end();
        rec.record(0, true, -1);
        if (clock.usable()) {
            assertTrue(r.cpuNs[0] >= 3_000_000, r.cpuNs[0] + " ns");
        } else {
            assertEquals(-1, r.cpuNs[0], clock.status());
        }
    }

    /**
     * A thread with its own clock (the rtsj engine's tasks, on RTSJ's real-time clock) gives the
     * times: stored from the run start on that clock; the CPU time from {@code startCpu} to the
     * record; a job that never started has no times.
     */
    @Test
    void aCallersClockGivesTheTimesAndTheCpuTimeBeginsAtStartCpu() {
        ThreadCpuClock clock = ThreadCpuClock.probe();
        JobRecords r = records();
        r.deadlineNs[0] = 2_000;
        r.deadlineNs[1] = 2_000;
        JobRecorder rec = new JobRecorder(r, clock, 0);
        rec.runStart(10_000);
        rec.startCpu();
        spin(clock, 3_000_000); // before the start: the wait for the robot and the doInterruptible's entry
        rec.started(11_000);
        rec.ended(12_000);
        rec.record(0, true, -1);
        rec.startCpu();
        rec.started(11_500);
        rec.ended(12_500);
        rec.record(1, false, 12_100);
        rec.recordNeverStarted(2);
        assertEquals(1_000, r.startNs[0]);
        assertEquals(2_000, r.endNs[0]);
        assertEquals(JobRecords.DONE, r.outcome[0], "ended at its deadline");
        assertEquals(JobRecords.TERMINATED, r.outcome[1]);
        assertEquals(2_100, r.abortSeenNs[1]);
        assertEquals(JobRecords.TERMINATED, r.outcome[2]);
        assertEquals(-1, r.startNs[2]);
        assertEquals(-1, r.endNs[2]);
        assertEquals(-1, r.cpuNs[2]);
        if (clock.usable()) {
            assertTrue(r.cpuNs[0] >= 3_000_000, "from startCpu: " + r.cpuNs[0] + " ns");
        } else {
            assertEquals(-1, r.cpuNs[0], clock.status());
        }
    }
}
