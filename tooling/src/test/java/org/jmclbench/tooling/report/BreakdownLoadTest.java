package org.jmclbench.tooling.report;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Map;

import org.junit.jupiter.api.Test;

/** The breakdown load read from a store's queue cells: the last count that held before the first that did not. */
class BreakdownLoadTest {

    static ReportModel.Cell cell(String config, int particles, int ok, int failed, double maxLate) {
        ReportModel.Cell c = new ReportModel.Cell();
        c.config = config;
        c.policy = "queue";
        c.particles = particles;
        c.runs = ok + failed;
        c.ok = ok;
        c.failed = failed;
        double[] late = new double[ok]; // the first repetition has the late jobs, the others none
        if (ok > 0) {
            late[0] = maxLate;
        }
        c.metrics.put(Metric.MISS_COUNT.name(), new ReportModel.Agg(ok, maxLate / ok, null, null, 0.0, maxLate, late));
        return c;
    }

    @Test
    void theBracketIsTheLastHeldCountAndTheFirstLateOne() {
        Map<String, BreakdownLoad> b = BreakdownLoad.of(List.of(
                cell("c", 100, 3, 0, 0), cell("c", 800, 3, 0, 0), cell("c", 400, 3, 0, 0),
                cell("c", 1600, 3, 0, 1), cell("c", 3200, 3, 0, 0), // held again above a failure: noise, not capacity
                cell("jvm", 100, 3, 0, 2),
                cell("all", 100, 3, 0, 0), cell("all", 200, 3, 0, 0)), List.of("c", "jvm", "all", "absent"));
        assertEquals(new BreakdownLoad(800, 1600, null, new BreakdownLoad.Late(1, 3, 1)), b.get("c"));
        assertEquals(new BreakdownLoad(null, 100, null, new BreakdownLoad.Late(1, 3, 2)), b.get("jvm"), "late already at the smallest count");
        assertEquals(new BreakdownLoad(200, null, null, null), b.get("all"), "every count held");
        assertFalse(b.containsKey("absent"));
    }

    @Test
    void countsThatHeldAboveTheFailingOneAreNamedWithTheirRepetitions() {
        List<ReportModel.Cell> cells = List.of(cell("c", 400, 3, 0, 0), cell("c", 800, 3, 0, 1), cell("c", 1600, 3, 0, 0),
                cell("c", 3200, 3, 0, 2), cell("c", 6400, 1, 0, 4), cell("jvm", 100, 3, 0, 2));
        // 1600 held in every repetition, 3200 late in one of three, 6400 in its only one
        assertEquals(List.of("1600 held in 3 of 3 repetitions", "3200 held in 2 of 3 repetitions"),
                BreakdownLoad.heldAbove(cells, "c", 800));
        assertEquals(List.of(), BreakdownLoad.heldAbove(cells, "jvm", 100), "nothing above the failing count");
        assertEquals(List.of(), BreakdownLoad.heldAbove(cells, "c", null), "nothing failed");
    }

    @Test
    void aFailedRepetitionFailsItsCount() {
        assertFalse(BreakdownLoad.held(cell("c", 100, 2, 1, 0)));
        assertNull(BreakdownLoad.of(List.of(cell("c", 100, 2, 1, 0)), List.of("c")).get("c").holds());
    }

    @Test
    void aCountWhoseRunsCrashedSaysSoInsteadOfPassingForALateJob() {
        ReportModel.Cell crashed = cell("hvm", 800, 0, 3, 0);
        crashed.metrics.clear();
        crashed.failures.add(new ReportModel.Failure(1, "failed", 1, "exit code 1: jmclbench: failure: the HVM executable failed"
                + " (exit status 139): warning: unimplemented function executed", null));
        assertEquals(new BreakdownLoad(400, 800, "3 of 3 runs failed: the HVM executable failed (exit status 139)", null),
                BreakdownLoad.of(List.of(cell("hvm", 400, 3, 0, 0), crashed), List.of("hvm")).get("hvm"));
        ReportModel.Cell once = cell("hvm", 800, 0, 1, 0);
        once.metrics.clear();
        once.failures.add(new ReportModel.Failure(1, "failed", 1, "exit code 1: jmclbench: failure: the HVM executable failed", null));
        assertEquals("1 of 1 run failed: the HVM executable failed",
                BreakdownLoad.of(List.of(cell("hvm", 400, 1, 0, 0), once), List.of("hvm")).get("hvm").failedRuns());
        assertNull(BreakdownLoad.of(List.of(cell("c", 100, 2, 1, 3)), List.of("c")).get("c").failedRuns(),
                "a completed run had a late job: the deadline bounds the load, whatever the failed one did");
    }

    @Test
    void aCountTheRuntimeCannotRunAboveOneThatHeldIsItsLimitNamed() {
        ReportModel.Cell past = cell("hvm", 66399, 0, 0, 0);
        past.metrics.clear();
        past.unsupported = 3;
        past.runs = 3;
        past.failures.add(new ReportModel.Failure(1, "unsupported", 3, "--particles 66399: the HVM holds at most 65,535"
                + " particles (its arrays hold at most 65,535 elements; docs/HVM.md)", null));
        assertEquals(new BreakdownLoad(60888, 66399, "the runtime cannot run it: the HVM holds at most 65,535 particles"
                + " (its arrays hold at most 65,535 elements; docs/HVM.md)", null),
                BreakdownLoad.of(List.of(cell("hvm", 60888, 3, 0, 0), past), List.of("hvm")).get("hvm"));
        assertEquals(new BreakdownLoad(null, null, null, null), BreakdownLoad.of(List.of(past), List.of("hvm")).get("hvm"),
                "a configuration none of whose counts ran has no breakdown load to bound");
    }

    @Test
    void aLateCountSaysInHowManyRepetitionsAndByHowManyJobs() {
        ReportModel.Cell c = cell("c", 800, 3, 0, 0);
        c.metrics.put(Metric.MISS_COUNT.name(), new ReportModel.Agg(3, 7.0 / 3, null, null, 0.0, 5.0, new double[] { 2, 0, 5 }));
        BreakdownLoad.Late late = BreakdownLoad.of(List.of(cell("c", 400, 3, 0, 0), c), List.of("c")).get("c").late();
        assertEquals(new BreakdownLoad.Late(2, 3, 5), late);
        assertEquals("2 of 3 repetitions late, by at most 5 jobs", late.toString());
        assertFalse(late.marginal(), "late in two repetitions is no single unlucky job");
        BreakdownLoad.Late one = BreakdownLoad.late(cell("c", 800, 3, 0, 1));
        assertEquals("1 of 3 repetitions late, by 1 job", one.toString());
        assertTrue(one.marginal());
        assertFalse(BreakdownLoad.late(cell("c", 800, 3, 0, 3)).marginal(), "three late jobs are more than a job or two");
    }
}
