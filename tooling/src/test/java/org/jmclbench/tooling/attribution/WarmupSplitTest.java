package org.jmclbench.tooling.attribution;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;

import java.util.List;
import java.util.Map;
import java.util.stream.Collectors;

import org.junit.jupiter.api.Test;

class WarmupSplitTest {
    private static final long MS = 1_000_000L;

    @Test
    void jobsReleasedBeforeTheBoundaryAreTheWarmPart() {
        List<JobRecord> jobs = List.of(
                new JobRecord("predict", 0, 0, 1 * MS, 31 * MS, 50 * MS, "done", 30 * MS),
                new JobRecord("predict", 1, 50 * MS, 60 * MS, 120 * MS, 100 * MS, "late", 60 * MS),
                new JobRecord("predict", 2, 2000 * MS, 2000 * MS, 2002 * MS, 2050 * MS, "done", 2 * MS),
                new JobRecord("predict", 3, 2050 * MS, 2051 * MS, 2055 * MS, 2100 * MS, "done", 4 * MS),
                new JobRecord("update", 0, 2100 * MS, -1, -1, 2200 * MS, "skipped", -1));
        Map<String, Double> m = WarmupSplit.metrics(jobs, 2000 * MS).stream()
                .collect(Collectors.toMap(r -> r.task() + "/" + r.metric() + "/" + r.stat(), MetricRow::value));
        assertEquals(2000.0 * MS, m.get("run/warmupBoundaryNs/value"));
        assertEquals(2.0, m.get("predict/taskLatencyNs.warm/count"));
        assertEquals(45.0 * MS, m.get("predict/taskLatencyNs.warm/mean"));
        assertEquals(60.0 * MS, m.get("predict/taskLatencyNs.warm/max"));
        assertEquals(30.0 * MS, m.get("predict/taskLatencyNs.warm/p50"), "nearest rank: index ceil(0.5 * 2) - 1 = 0");
        assertEquals(70.0 * MS, m.get("predict/responseTimeNs.warm/max"));
        assertEquals(3.0 * MS, m.get("predict/taskLatencyNs.steady/mean"));
        assertEquals(1.0, m.get("predict/missedOrLate.warm/value"));
        assertEquals(0.0, m.get("predict/missedOrLate.steady/value"));
        assertEquals(1.0, m.get("update/missedOrLate.steady/value"));
        assertEquals(0.0, m.get("update/taskLatencyNs.steady/count"));
        assertFalse(m.containsKey("update/taskLatencyNs.steady/mean"), "no stats rows for an empty sample");
        assertEquals(3.0, m.get("all/released.steady/value"));
    }
}
