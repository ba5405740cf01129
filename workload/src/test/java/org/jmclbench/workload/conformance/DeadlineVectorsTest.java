package org.jmclbench.workload.conformance;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.util.ArrayList;
import java.util.List;

import org.jmclbench.core.record.JobRecords;
import org.jmclbench.core.timeline.Timeline;
import org.jmclbench.workload.conformance.VectorFile.Line;
import org.jmclbench.workload.output.TaskSummary;
import org.jmclbench.workload.record.Stats;
import org.junit.jupiter.api.Test;

/**
 * summary.json's deadline accounting, response time over every release and abort latency
 * (FORMATS.md section 4) against conformance/deadlines.txt, which the C baseline checks too: the same job records give
 * the same numbers in both languages.
 */
class DeadlineVectorsTest {

    @Test
    void accountingAndReleasedResponseTimesFollowTheReference() throws IOException {
        List<Line> lines = VectorFile.read("deadlines.txt").lines;
        int cases = 0;
        int checks = 0;
        for (int i = 0; i < lines.size(); i++) {
            Line c = lines.get(i);
            assertEquals("case", c.kind(), c.where);
            int n = c.integer(2);
            List<Line> jobs = lines.subList(i + 1, i + 1 + n);
            JobRecords r = records(jobs);
            i += n + 1;
            for (; !lines.get(i).kind().equals("end"); i++) {
                Line l = lines.get(i);
                String task = l.tokens[1];
                TaskSummary s = TaskSummary.count(r, task.equals("all") ? -1
                        : task.equals("predict") ? Timeline.PREDICT : Timeline.UPDATE);
                if (l.kind().equals("count")) {
                    int[] expected = {l.integer(2), l.integer(3), l.integer(4), l.integer(5), l.integer(6), l.integer(7)};
                    int[] actual = {s.released(), s.done(), s.late(), s.skipped(), s.terminated(), s.deadlineMisses()};
                    for (int k = 0; k < expected.length; k++) {
                        assertEquals(expected[k], actual[k], l.where + ": column " + (k + 2));
                    }
                    if (l.tokens[8].equals("null")) {
                        assertTrue(Double.isNaN(s.missRatio()), l.where + ": missRatio of nothing released");
                    } else {
                        assertEquals(l.hexDouble(8), s.missRatio(), 0.0, l.where + ": missRatio, bit for bit");
                    }
                } else if (l.kind().equals("abort")) {
                    Stats a = s.abortLatency();
                    assertEquals(l.integer(2), a.count, l.where + ": count");
                    assertEquals(l.integer(3), s.abortsCompleted(), l.where + ": completed");
                    long[] got = {a.min, a.p50, a.p90, a.p99, a.p999, a.max};
                    for (int q = 0; q < 6; q++) {
                        String want = l.tokens[4 + q];
                        assertEquals(want, a.count == 0 ? "null" : Long.toString(got[q]), l.where + ": quantile " + q);
                    }
                } else {
                    assertEquals("response", l.kind(), l.where);
                    assertEquals(l.integer(2), s.released(), l.where + ": count");
                    for (int q = 0; q < 6; q++) {
                        String want = l.tokens[4 + q];
                        if (want.equals("null")) {
                            assertEquals(0, s.released(), l.where);
                            continue;
                        }
                        long got = s.releasedResponse(q);
                        String gotText = got == Stats.NOT_COMPLETED ? "inf" : Long.toString(got);
                        assertEquals(want, gotText, l.where + ": quantile " + q);
                    }
                }
                checks++;
            }
            cases++;
        }
        assertTrue(cases >= 7 && checks == 9 * cases, cases + " cases, " + checks + " checks");
    }

    /**
     * Job records of the vector's job lines: the k-th line is the k-th event (its time is its
     * line number, so the merged timeline keeps the file's order).
     */
    private static JobRecords records(List<Line> jobs) {
        List<Double> odo = new ArrayList<>();
        List<Double> laser = new ArrayList<>();
        for (int k = 0; k < jobs.size(); k++) {
            (jobs.get(k).tokens[1].equals("predict") ? odo : laser).add((double) k);
        }
        Timeline t = Timeline.merge(odo.stream().mapToDouble(Double::doubleValue).toArray(),
                laser.stream().mapToDouble(Double::doubleValue).toArray());
        JobRecords r = new JobRecords(t, false);
        for (int k = 0; k < jobs.size(); k++) {
            Line l = jobs.get(k);
            assertEquals(l.tokens[1].equals("predict") ? Timeline.PREDICT : Timeline.UPDATE, t.task(k), l.where);
            r.outcome[k] = outcome(l.tokens[2]);
            r.releaseNs[k] = Long.parseLong(l.tokens[3]);
            r.startNs[k] = Long.parseLong(l.tokens[4]);
            r.endNs[k] = Long.parseLong(l.tokens[5]);
            r.abortNs[k] = Long.parseLong(l.tokens[6]);
        }
        return r;
    }

    private static byte outcome(String name) {
        for (byte b = JobRecords.PENDING; b <= JobRecords.TERMINATED; b++) {
            if (JobRecords.outcomeName(b).equals(name)) {
                return b;
            }
        }
        throw new IllegalArgumentException("unknown outcome " + name);
    }
}
