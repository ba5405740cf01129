package org.jmclbench.tooling.attribution;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

class AttributionTest {
    private static final long MS = 1_000_000L;
    private static final Attribution.Settings DEFAULTS = Attribution.Settings.defaults();

    // --- on recorded runs: a periodic job beside a noise thread on a 48 MB Serial heap ---

    @ParameterizedTest
    @ValueSource(strings = {"jdk11", "jdk17", "jdk21", "jdk25"})
    void lateJobsOfARecordedRunUnderAllocationAreAttributedToGcPausesFromJfr(String jdk) throws Exception {
        Path d = Fixtures.dir(jdk);
        List<JobAttribution> a = Attribution.attribute(JobFileReader.read(d.resolve("jobs.txt"), "predict"),
                JfrEventReader.read(d.resolve("recording.jfr"), RunClock.fromText(d.resolve("clock.txt"))), DEFAULTS);
        assertGcAndCompute(jdk, a);
        assertTrue(a.stream().anyMatch(j -> j.primary().kind().equals("gc")), jdk + ": some miss is mainly a GC pause");
    }

    @ParameterizedTest
    @ValueSource(strings = {"jdk11", "jdk17", "jdk21", "jdk25", "jdk11/uptime", "jdk25/uptime"})
    void theGcLogAloneAlsoExplainsThem(String fixture) throws Exception {
        Path d = Fixtures.dir(fixture);
        List<JobAttribution> a = Attribution.attribute(JobFileReader.read(d.resolve("jobs.txt"), "predict"),
                GcLogParser.parse(d.resolve("gc.log"), RunClock.fromText(d.resolve("clock.txt"))), DEFAULTS);
        assertGcAndCompute(fixture, a);
    }

    private static void assertGcAndCompute(String name, List<JobAttribution> a) {
        assertTrue(a.stream().anyMatch(j -> j.causes().stream().anyMatch(c -> c.kind().equals("gc") && c.ns() >= MS)),
                name + ": a late job overlaps a GC pause of a millisecond or more");
        JobAttribution slow = a.stream().filter(j -> j.index() == Fixtures.SLOW_JOB).findFirst().orElseThrow();
        Cause compute = slow.causes().stream().filter(c -> c.kind().equals("compute")).findFirst().orElseThrow(
                () -> new AssertionError(name + ": the slow job is compute: " + slow));
        assertTrue(compute.ns() >= 30 * MS, compute.toString());
        for (JobAttribution j : a) {
            assertTrue(!j.causes().isEmpty());
        }
    }

    // --- synthetic runs: each rule on its own ---

    private static JobRecord job(String task, int i, long release, long start, long end, long deadline, String outcome, long cpu) {
        return new JobRecord(task, i, release * MS, start < 0 ? -1 : start * MS, end < 0 ? -1 : end * MS,
                deadline * MS, outcome, cpu < 0 ? -1 : cpu * MS);
    }

    private static VmEvent ev(VmEventKind k, long from, long to, String thread, String detail) {
        return new VmEvent(k, from * MS, to * MS, thread, detail);
    }

    @Test
    void aLateJobDuringAPauseIsAttributedToTheCollectorNotToTheSafepointAroundIt() {
        List<JobRecord> jobs = List.of(job("predict", 0, 0, 0, 60, 50, "late", 20));
        List<VmEvent> ev = List.of(ev(VmEventKind.SAFEPOINT, 9, 50, null, "G1CollectForAllocation"),
                ev(VmEventKind.GC_PAUSE, 10, 50, null, "G1New Pause Young"));
        JobAttribution a = Attribution.attribute(jobs, ev, DEFAULTS).get(0);
        assertEquals("gc", a.primary().kind());
        assertEquals(40 * MS, a.primary().ns());
        assertEquals(1 * MS, a.causes().get(1).ns(), "the safepoint's own part: time to reach it");
        assertEquals("safepoint", a.causes().get(1).kind());
    }

    @Test
    void aJobWhoseCpuTimeAloneExceedsItsDeadlineIsCompute() {
        List<JobAttribution> a = Attribution.attribute(List.of(job("update", 3, 100, 100, 190, 180, "late", 88)), List.of(), DEFAULTS);
        assertEquals("compute", a.get(0).primary().kind());
        assertEquals(1, a.get(0).causes().size());
    }

    @Test
    void aJobThatStartsLateWithNothingInTheWayIsTheOs() {
        List<JobAttribution> a = Attribution.attribute(List.of(job("predict", 0, 0, 30, 55, 50, "late", 24)), List.of(), DEFAULTS);
        assertEquals(List.of("os"), a.get(0).causes().stream().map(Cause::kind).toList());
        assertEquals(30 * MS, a.get(0).primary().ns());
    }

    @Test
    void aJobThatWaitedForAnotherIsQueuedBehindIt() {
        List<JobRecord> jobs = List.of(job("update", 0, 0, 0, 70, 100, "done", 69),
                job("predict", 1, 50, 70, 110, 100, "late", 39));
        JobAttribution a = Attribution.attribute(jobs, List.of(), DEFAULTS).get(0);
        assertEquals("predict", a.task());
        assertEquals("queued", a.primary().kind());
        assertEquals(20 * MS, a.primary().ns());
        assertTrue(a.primary().detail().contains("update#0"));
        assertEquals(1, a.causes().size(), a.toString());
    }

    @Test
    void aPauseDuringTheJobItWaitedForIsTheGcNotAlsoQueuedAndTheRestIsTheOs() {
        // update#0 holds the robot 0-50 ms, 30 ms of it inside a GC pause (10-40); predict#1, released
        // at 10, starts only at 80: 10 ms waiting for update#0's work, 30 ms for the pause, 30 ms for the OS.
        List<JobRecord> jobs = List.of(job("update", 0, 0, 0, 50, 100, "done", 20),
                job("predict", 1, 10, 80, 85, 50, "late", 5));
        JobAttribution a = Attribution.attribute(jobs, List.of(ev(VmEventKind.GC_PAUSE, 10, 40, null, "Serial")), DEFAULTS).get(0);
        Map<String, Long> ns = new java.util.TreeMap<>();
        a.causes().forEach(c -> ns.put(c.kind(), c.ns()));
        assertEquals(Map.of("gc", 30 * MS, "os", 30 * MS, "queued", 10 * MS), ns, a.toString());
        long sum = a.causes().stream().mapToLong(Cause::ns).sum();
        assertTrue(sum <= a.windowEndNs() - a.windowStartNs(), "the causes add up to at most the window: " + a);
    }

    @Test
    void wallTimeFarAboveCpuTimeWithoutPausesIsPreemption() {
        List<JobAttribution> a = Attribution.attribute(List.of(job("predict", 0, 0, 0, 60, 50, "late", 10)), List.of(), DEFAULTS);
        assertEquals("preemption", a.get(0).primary().kind());
        assertEquals(50 * MS, a.get(0).primary().ns());
        // The same job inside a 45 ms pause: the pause explains the off-CPU time.
        a = Attribution.attribute(List.of(job("predict", 0, 0, 0, 60, 50, "late", 10)),
                List.of(ev(VmEventKind.GC_PAUSE, 5, 50, null, "Serial")), DEFAULTS);
        assertEquals(List.of("gc", "preemption"), a.get(0).causes().stream().map(Cause::kind).toList());
        assertEquals(5 * MS, a.get(0).causes().get(1).ns());
    }

    @Test
    void aSkippedJobTakesTheCausesOfTheJobThatHeldTheRobot() {
        List<JobRecord> jobs = List.of(job("update", 0, 0, 0, 80, 200, "done", 75),
                job("predict", 1, 50, -1, -1, 100, "skipped", -1),
                job("predict", 2, 100, 100, 101, 150, "done", 1));
        List<VmEvent> ev = List.of(ev(VmEventKind.GC_PAUSE, 200, 210, null, "after"));
        JobAttribution a = Attribution.attribute(jobs, ev, DEFAULTS).get(0);
        assertEquals("skipped", a.outcome());
        assertEquals("update#0", a.blockedBy());
        assertEquals(0, a.windowStartNs());
        assertEquals(80 * MS, a.windowEndNs());
        assertEquals(List.of("compute"), a.causes().stream().map(Cause::kind).toList());
    }

    @Test
    void aJobReleasedButNotYetStartedHoldsTheRobot() {
        // predict#0 released at 0 starts only at 40 (the OS), so predict#1 released at 20 is skipped behind it.
        List<JobRecord> jobs = List.of(job("predict", 0, 0, 40, 45, 50, "done", 5),
                job("predict", 1, 20, -1, -1, 70, "skipped", -1));
        JobAttribution a = Attribution.attribute(jobs, List.of(), DEFAULTS).get(0);
        assertEquals("predict#0", a.blockedBy());
        assertEquals(List.of("os"), a.causes().stream().map(Cause::kind).toList());
        assertEquals(40 * MS, a.primary().ns());
    }

    @Test
    void jitIsListedAfterCausesDuringWhichTheJobStoodStill() {
        List<JobRecord> jobs = List.of(job("predict", 0, 0, 0, 60, 50, "late", 20));
        List<VmEvent> ev = List.of(ev(VmEventKind.GC_PAUSE, 10, 30, null, "Serial"),
                ev(VmEventKind.COMPILATION, 0, 60, "C2 CompilerThread0", "org.jmclbench.core.mcl.X.y level 4"));
        JobAttribution a = Attribution.attribute(jobs, ev, DEFAULTS).get(0);
        assertEquals(List.of("gc", "preemption", "jit"), a.causes().stream().map(Cause::kind).toList());
    }

    @Test
    void aSkippedJobBehindABlockerThatRanNormallyIsAnOverlap() {
        // predict#0: released at 0, started 0.25 ms late, 0.25 ms of CPU; update#0 released at 0.35 ms.
        List<JobRecord> jobs = List.of(new JobRecord("predict", 0, 0, 250_000, 510_000, 50 * MS, "done", 250_000),
                new JobRecord("update", 0, 350_000, -1, -1, 100 * MS, "skipped", -1));
        JobAttribution a = Attribution.attribute(jobs, List.of(), DEFAULTS).get(0);
        assertEquals(List.of("overlap"), a.causes().stream().map(Cause::kind).toList());
        assertEquals(160_000, a.primary().ns());
        assertTrue(a.primary().detail().contains("predict#0"), a.primary().detail());
    }

    @Test
    void aTerminatedJobSupersededBeforeItStartedIsTheOverlapOfTheTwoReleases() {
        // terminate: predict#14 released at 225 ms, update#6 at 225.086 ms, before predict#14's
        // handler had started it; the robot was free (predict#13 ended at 212 ms)
        List<JobRecord> jobs = List.of(new JobRecord("predict", 13, 210 * MS, 211 * MS, 212 * MS, 225 * MS, "done", -1),
                new JobRecord("predict", 14, 225 * MS, -1, -1, 240 * MS, "terminated", -1),
                new JobRecord("update", 6, 225_086_000, 225_190_000, 226_500_000, 237 * MS, "done", -1));
        JobAttribution a = Attribution.attribute(jobs, List.of(), DEFAULTS).get(0);
        assertEquals(List.of("overlap"), a.causes().stream().map(Cause::kind).toList());
        // not 15 ms of "unknown" up to its deadline: it was over when update#6 was released
        assertEquals(86_000, a.primary().ns());
        assertEquals(225_086_000, a.windowEndNs());
        assertTrue(a.primary().detail().contains("update#6"), a.primary().detail());
    }

    @Test
    void aJobAbortedWhileItRanNormallyIsTheOverlapOfTheTwoReleases() {
        // terminate, as measured: predict#8 released at 400 ms, started at once, 2.24 ms later update#4
        // was released and aborted it at 402.35 ms; 2.3 ms of CPU for a 15 ms deadline, no runtime event
        List<JobRecord> jobs = List.of(new JobRecord("predict", 8, 400 * MS, 400_010_000, 402_350_000, 415 * MS, "terminated",
                        2_300_000),
                new JobRecord("update", 4, 402_240_000, 402_400_000, 410 * MS, 430 * MS, "done", 7 * MS));
        JobAttribution a = Attribution.attribute(jobs, List.of(), DEFAULTS).get(0);
        // it was "unknown" over its window: nothing went wrong with it, the next event came first
        assertEquals(List.of("overlap"), a.causes().stream().map(Cause::kind).toList());
        assertEquals(2_350_000, a.primary().ns());
        assertTrue(a.primary().detail().contains("update#4") && a.primary().detail().contains("2.240 ms"), a.primary().detail());
    }

    @Test
    void aSkippedJobBehindABlockerStalledByAPauseIsTheGc() {
        List<JobRecord> jobs = List.of(job("update", 0, 0, 0, 70, 200, "done", 5),
                job("predict", 1, 50, -1, -1, 100, "skipped", -1));
        JobAttribution a = Attribution.attribute(jobs, List.of(ev(VmEventKind.GC_PAUSE, 2, 66, null, "Serial")), DEFAULTS).get(0);
        assertEquals(List.of("gc"), a.causes().stream().map(Cause::kind).toList());
    }

    @Test
    void jitCountsOnlyTheJobsOwnCodeAndClassLoadingOnlyItsOwnThread() {
        List<JobRecord> jobs = List.of(job("update", 0, 0, 0, 60, 50, "late", 59));
        List<VmEvent> ev = List.of(
                ev(VmEventKind.COMPILATION, 10, 20, "C2 CompilerThread0", "java.util.HashMap.get level 4"),
                ev(VmEventKind.COMPILATION, 30, 35, "C2 CompilerThread0", "org.jmclbench.core.mcl.Likelihood.weigh level 4"),
                ev(VmEventKind.CLASS_LOAD, 1, 3, "jmclbench-predict-handler", "a.B"),
                ev(VmEventKind.CLASS_LOAD, 4, 6, "jmclbench-update-handler", "a.C"),
                ev(VmEventKind.THREAD_BLOCKED, 40, 44, "jmclbench-update-handler", "park"));
        JobAttribution a = Attribution.attribute(jobs, ev, DEFAULTS).get(0);
        Map<String, Cause> byKind = new java.util.HashMap<>();
        a.causes().forEach(c -> byKind.put(c.kind(), c));
        assertEquals(5 * MS, byKind.get("jit").ns());
        assertTrue(byKind.get("jit").detail().contains("Likelihood.weigh"));
        assertEquals(2 * MS, byKind.get("classload").ns());
        assertEquals("a.C 2.000 ms", byKind.get("classload").detail());
        assertEquals(4 * MS, byKind.get("lock").ns());
        assertEquals("compute", a.primary().kind());
    }

    @Test
    void aPauseWhileTheHandlerWaitedIsTheGcNotAlsoTheWait() {
        // update#0 computes 0-20 ms (20 ms of CPU for a 15 ms deadline), then waits on its thread 20-60,
        // a GC pause 30-40 inside the wait: 20 ms compute, 10 ms gc, 30 ms lock; the pause counted in
        // the wait too made 70 ms of causes in a 60 ms window.
        List<JobRecord> jobs = List.of(job("update", 0, 0, 0, 60, 15, "late", 20));
        List<VmEvent> ev = List.of(ev(VmEventKind.THREAD_BLOCKED, 20, 60, "jmclbench-update-handler", "park"),
                ev(VmEventKind.GC_PAUSE, 30, 40, null, "Serial"));
        JobAttribution a = Attribution.attribute(jobs, ev, DEFAULTS).get(0);
        Map<String, Long> ns = new java.util.TreeMap<>();
        a.causes().forEach(c -> ns.put(c.kind(), c.ns()));
        assertEquals(Map.of("compute", 20 * MS, "gc", 10 * MS, "lock", 30 * MS), ns, a.toString());
        // The same wait of a job preempted for 10 ms more (0-70, 20 ms of CPU): preemption is its 10 ms, the
        // pause and the wait taken out once each.
        a = Attribution.attribute(List.of(job("update", 0, 0, 0, 70, 15, "late", 20)), ev, DEFAULTS).get(0);
        ns.clear();
        a.causes().forEach(c -> ns.put(c.kind(), c.ns()));
        assertEquals(Map.of("compute", 20 * MS, "gc", 10 * MS, "lock", 30 * MS, "preemption", 10 * MS), ns, a.toString());
    }

    @Test
    void aTerminatedJobIsExplainedOverItsReleaseToItsAbort() {
        // update#0 aborted at 40 by the next release; it had used 38 ms of CPU for a 35 ms deadline.
        List<JobRecord> jobs = List.of(job("update", 0, 0, 0, 40, 35, "terminated", 38));
        JobAttribution a = Attribution.attribute(jobs, List.of(ev(VmEventKind.GC_PAUSE, 50, 60, null, "later")), DEFAULTS).get(0);
        assertEquals("terminated", a.outcome());
        assertEquals(40 * MS, a.windowEndNs());
        assertEquals(List.of("compute"), a.causes().stream().map(Cause::kind).toList());
    }

    @Test
    void nothingFoundIsUnknownAndDoneJobsAreNotAttributed() {
        List<JobRecord> jobs = new ArrayList<>(List.of(job("predict", 0, 0, 0, 51, 50, "late", 50),
                job("predict", 1, 50, 51, 60, 100, "done", 9)));
        List<JobAttribution> a = Attribution.attribute(jobs, List.of(), DEFAULTS);
        assertEquals(1, a.size());
        assertEquals("unknown", a.get(0).primary().kind());
        assertNull(a.get(0).blockedBy());
        assertEquals(Map.of("unknown", 1), Attribution.countCauses(a));
    }

    @Test
    void countsEachKindOncePerJobAndPrimaryCausesPartitionTheJobs() {
        List<JobRecord> jobs = List.of(job("predict", 0, 0, 0, 60, 50, "late", 10),
                job("predict", 1, 100, 100, 200, 150, "late", 99));
        List<VmEvent> ev = List.of(ev(VmEventKind.GC_PAUSE, 5, 10, null, "a"), ev(VmEventKind.GC_PAUSE, 20, 25, null, "b"),
                ev(VmEventKind.GC_PAUSE, 110, 111, null, "c"));
        List<JobAttribution> a = Attribution.attribute(jobs, ev, DEFAULTS);
        assertEquals(Map.of("gc", 2, "preemption", 1, "compute", 1), Attribution.countCauses(a));
        assertEquals(Map.of("preemption", 1, "compute", 1), Attribution.countPrimaryCauses(a));
    }
}
