package org.jmclbench.workload.output;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.jmclbench.core.policy.OverrunPolicy;
import org.jmclbench.core.record.JobRecords;
import org.jmclbench.core.timeline.Timeline;
import org.jmclbench.workload.RunOptions;
import org.junit.jupiter.api.Test;

/**
 * The deadline accounting keys of a task in summary.json (FORMATS.md section 4): written after the
 * thesis's keys, a dropped job as "inf" among the released quantiles, null when nothing was released,
 * and missCount still the thesis's per policy. The numbers themselves: conformance/deadlines.txt.
 */
class TaskSummaryTest {

    /** Three predict jobs: done in 2 ms, late in 60 ms, skipped; no update job. */
    private static JobRecords records() {
        JobRecords r = new JobRecords(Timeline.merge(new double[] {0, 1, 2}, new double[0]), false);
        byte[] out = {JobRecords.DONE, JobRecords.LATE, JobRecords.SKIPPED};
        long[] end = {2_000_000, 160_000_000, -1};
        for (int k = 0; k < 3; k++) {
            r.outcome[k] = out[k];
            r.releaseNs[k] = 100_000_000L * k;
            r.startNs[k] = end[k] < 0 ? -1 : r.releaseNs[k];
            r.endNs[k] = end[k] < 0 ? -1 : r.releaseNs[k] + end[k] - (k == 1 ? 100_000_000 : 0);
            r.deadlineNs[k] = r.releaseNs[k] + 50_000_000;
        }
        return r;
    }

    private static String json(TaskSummary s) {
        Json j = new Json();
        s.writeTo(j);
        return j.toString();
    }

    @Test
    void aDroppedJobIsAnInfiniteResponseTimeAndAMiss() {
        RunOptions skip = new RunOptions();
        String text = json(TaskSummary.of(records(), Timeline.PREDICT, skip));
        assertTrue(text.contains("  \"missCount\": 1,\n"), text); // the thesis's: skipped + terminated
        String tail = text.substring(text.indexOf("  \"deadlineMisses\""));
        assertEquals("  \"deadlineMisses\": 2,\n  \"missRatio\": 0.6666666666666666,\n"
                + "  \"responseTimeReleasedNs\": {\n    \"count\": 3,\n    \"completed\": 2,\n    \"min\": 2000000,\n"
                + "    \"p50\": 60000000,\n    \"p90\": \"inf\",\n    \"p99\": \"inf\",\n    \"p999\": \"inf\",\n"
                + "    \"max\": \"inf\"\n  }\n}\n", tail);
        assertTrue(text.indexOf("\"cpuNs\"") < text.indexOf("\"deadlineMisses\""), "new keys after the thesis's");
    }

    /** {@link #records()} with job 1 (started at 100 ms) asked to abort at 110 ms and ended at 110.05 ms. */
    private static JobRecords withAnAbort() {
        JobRecords r = records();
        r.outcome[1] = JobRecords.TERMINATED;
        r.endNs[1] = 110_050_000;
        r.requestAbort(1, 110_000_000);
        return r;
    }

    @Test
    void theAbortLatencySplitsAtTheMomentTheJobSawTheRequest() {
        JobRecords r = withAnAbort();
        r.abortSeen(1, 110_020_000);
        r.abortSeen(1, 110_040_000); // a later poll changes nothing
        // job 0 asked after its end: nothing took hold, so its seen time does not count
        r.requestAbort(0, 3_000_000);
        r.abortSeen(0, 3_000_000);
        TaskSummary s = TaskSummary.count(r, Timeline.PREDICT);
        assertEquals(1, s.abortLatency().count);
        assertEquals(50_000, s.abortLatency().max);
        assertEquals(1, s.abortNotice().count);
        assertEquals(20_000, s.abortNotice().max);
        assertEquals(30_000, s.abortStop().max);
        assertEquals(110_020_000, r.abortSeenFromNs(1));
        assertEquals(-1, r.abortSeenFromNs(0));
    }

    @Test
    void anEngineThatDoesNotRecordWhenTheJobSawItHasNoSplit() {
        TaskSummary s = TaskSummary.count(withAnAbort(), Timeline.PREDICT);
        assertEquals(1, s.abortLatency().count);
        assertEquals(0, s.abortNotice().count);
        assertTrue(json(s).contains("\"abortNoticeNs\": {\n    \"count\": 0"), json(s));
    }

    @Test
    void underQueueMissCountIsTheLateJobsAndTheAccountingIsUnchanged() {
        RunOptions queue = new RunOptions();
        queue.policy = OverrunPolicy.QUEUE;
        TaskSummary s = TaskSummary.of(records(), -1, queue);
        assertEquals(1, s.missCount);
        assertEquals(2, s.deadlineMisses());
        assertEquals(2.0 / 3.0, s.missRatio(), 0.0);
    }

    @Test
    void nothingReleasedWritesNulls() {
        String text = json(TaskSummary.of(records(), Timeline.UPDATE, new RunOptions()));
        assertTrue(text.contains("\"deadlineMisses\": 0,\n  \"missRatio\": null,\n"), text);
        assertTrue(text.contains("\"count\": 0,\n    \"completed\": 0,\n    \"min\": null,"), text);
        assertTrue(text.contains("\"max\": null\n  }\n}\n"), text);
    }
}
