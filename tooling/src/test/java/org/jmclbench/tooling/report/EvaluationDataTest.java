package org.jmclbench.tooling.report;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;

import org.jmclbench.tooling.store.StoredRun;
import org.junit.jupiter.api.Test;

/** The evaluation's statistics API on cells whose answer is known. */
class EvaluationDataTest {

    private static ReportModel.Cell cell(String config, double... misses) {
        ReportModel.Cell c = new ReportModel.Cell();
        c.config = config;
        c.ok = misses.length;
        List<Double> values = new ArrayList<>();
        for (double m : misses) {
            values.add(m);
        }
        c.metrics.put(Metric.MISS_COUNT.name(), ReportModel.Agg.of(values));
        return c;
    }

    @Test
    void aggregatesAreMeanWithABootstrapIntervalThatStaysAboveZero() {
        assertEquals("0.3 [0.0, 1.0]", EvaluationData.agg(cell("hvm", 0, 0, 1), Metric.MISS_COUNT, 1));
        assertEquals("2.0", EvaluationData.agg(cell("hvm", 2), Metric.MISS_COUNT, 1), "one run: no interval");
        assertEquals("n/a", EvaluationData.agg(cell("hvm", 2), Metric.LATENCY_MEAN, 3));
    }

    @Test
    void theSeparationSentenceNamesTheTestAndNeverRanksThreeRuns() {
        // the Figure 3: C with 0.0 misses ranked above the HVM with 0.3, three runs each
        ReportModel.Cell c = cell("native", 0, 0, 0);
        ReportModel.Cell hvm = cell("hvm", 0, 0, 1);
        String few = EvaluationData.separationSentence(EvaluationData.separationOf(c, hvm, Metric.MISS_COUNT), c, hvm);
        assertTrue(few.startsWith("Mann-Whitney U with the bootstrap interval of the ratio (docs/REPORT.md): not separated: n too small to "
                + "separate (p = "), few);
        assertTrue(few.endsWith(", n = 3 vs 3; 10 a side needed)."), few);
        double[] none = new double[10];
        double[] some = {5, 6, 7, 5, 6, 7, 5, 6, 7, 6};
        Separation.Result r = EvaluationData.separationOf(cell("native", none), cell("temurin-25", some), Metric.MISS_COUNT);
        assertEquals(Separation.Verdict.A_LOWER, r.verdict());
        assertEquals("native lower than temurin-25 (p < 0.001, n = 10 vs 10)", r.text("native", "temurin-25"));
        assertEquals(Separation.Verdict.TOO_FEW,
                EvaluationData.separationOf(cell("native", none), cell("x"), Metric.LATENCY_MEAN).verdict(), "no values: too few");
    }

    @Test
    void eachCellKnowsWhichCellsOfItsSettingItIsSeparatedFrom() {
        ReportModel.Cell none = cell("native", new double[10]);
        ReportModel.Cell some = cell("temurin-25", 5, 6, 7, 5, 6, 7, 5, 6, 7, 6);
        ReportModel.Cell three = cell("hvm", 0, 0, 1);
        ReportModel.Cell elsewhere = cell("zgc", 9, 9, 9, 9, 9, 9, 9, 9, 9, 9);
        for (ReportModel.Cell c : List.of(none, some, three, elsewhere)) {
            c.dataset = "d";
            c.policy = "skip";
            c.particles = c == elsewhere ? 800 : 100;
        }
        CellAggregates.separateMisses(List.of(none, some, three, elsewhere));
        assertEquals("A_LOWER", none.missSeparation.get("temurin-25"));
        assertEquals("B_LOWER", some.missSeparation.get("native"), "the same verdict seen from the other side");
        assertEquals("TOO_FEW", none.missSeparation.get("hvm"));
        assertEquals(List.of("temurin-25", "hvm"), List.copyOf(none.missSeparation.keySet()), "only the cells of its setting");
        assertTrue(elsewhere.missSeparation.isEmpty());
    }

    @Test
    void aMemoryAreaSaysHowManyReleasesAllocated() {
        assertEquals("update 248 B (1 of 270 releases allocated, 3 B/release)",
                EvaluationData.areaText(new ReportModel.MemoryArea("update", 4096L, 248L, 2.8, 3, 270L, 1L)));
        assertEquals("immortal 0 B", EvaluationData.areaText(new ReportModel.MemoryArea("immortal", 55_316L, 0L, null, 3, null, null)));
    }

    @Test
    void aTasksMissRatioIsPooledOverTheRunsWithAWilsonInterval() {
        List<StoredRun> runs = new ArrayList<>();
        for (int missed : new int[] {0, 3, 2}) {
            StoredRun r = new StoredRun();
            r.summaryJson = "{\"tasks\": {\"update\": {\"released\": 100, \"deadlineMisses\": " + missed + "},"
                    + " \"predict\": {\"released\": 200, \"late\": 1, \"skipped\": 0, \"terminated\": 0}}}";
            runs.add(r);
        }
        ReportModel.Cell c = new ReportModel.Cell();
        c.deadlines = CellAggregates.deadlines(runs);
        Stats.Interval update = EvaluationData.missRatio(c, "update");
        assertEquals(Stats.wilson(5, 300), update);
        assertEquals(5.0 / 300, update.estimate(), 1e-12);
        assertTrue(update.low() > 0 && update.high() < 0.04, update.toString());
        assertEquals(Stats.wilson(3, 600), EvaluationData.missRatio(c, "predict"), "late + skipped + terminated without deadlineMisses");
        assertTrue(Double.isNaN(EvaluationData.missRatio(c, "all").estimate()), "a task no run reported");
    }

    @Test
    void aWindowsMissRatioIsPooledOverTheRunsSoThatWindowsOfOtherLengthsCompare() {
        ReportModel.Cell c = new ReportModel.Cell();
        c.metrics.put("WARM_MISSES", ReportModel.Agg.of(List.of(1.0, 2.0, 2.0)));
        c.metrics.put("WARM_RELEASED", ReportModel.Agg.of(List.of(40.0, 40.0, 40.0)));
        c.metrics.put("STEADY_MISSES", ReportModel.Agg.of(List.of(30.0, 34.0, 38.0)));
        c.metrics.put("STEADY_RELEASED", ReportModel.Agg.of(List.of(2600.0, 2600.0, 2600.0)));
        assertEquals(Stats.wilson(5, 120), EvaluationData.windowMissRatio(c, "WARM"));
        assertEquals(Stats.wilson(102, 7800), EvaluationData.windowMissRatio(c, "STEADY"));
        assertTrue(EvaluationData.windowMissRatio(c, "WARM").estimate() > EvaluationData.windowMissRatio(c, "STEADY").estimate(),
                "fewer jobs missed in the warm-up, but a larger share of them");
        c.metrics.remove("STEADY_RELEASED");
        assertTrue(Double.isNaN(EvaluationData.windowMissRatio(c, "STEADY").estimate()), "a store without the released counts");
    }
}
