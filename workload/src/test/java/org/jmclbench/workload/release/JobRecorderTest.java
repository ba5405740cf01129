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
}
