package org.jmclbench.scj;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.util.concurrent.atomic.AtomicIntegerArray;

import org.jmclbench.core.mcl.AbortSignal;
import org.jmclbench.core.mcl.DelegatingLocalizer;
import org.jmclbench.core.mcl.Localizer;
import org.jmclbench.core.mcl.MclConfig;
import org.jmclbench.core.mcl.Playground;
import org.jmclbench.core.mcl.PreallocatedLocalizer;
import org.jmclbench.core.policy.OverrunPolicy;
import org.jmclbench.core.record.JobRecords;
import org.jmclbench.core.timeline.Timeline;
import org.jmclbench.rtsjcompat.AreaUsage;
import org.jmclbench.rtsjcompat.RunReport;
import org.jmclbench.rtsjcompat.ScjRuntime;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

/**
 * The whole mission on rtsj-compat (Level 1, real threads and time). No assertion depends on
 * timing: where a property needs an unloaded machine (every job done before the next release),
 * the test checks that from the records and is skipped, not failed, when the machine was busy.
 */
class MissionTest {
    /** One finished launch: the safelet (its mission and entry), the records handed over and compat's report. */
    static final class Launch implements MissionOutput {
        MclSafelet safelet;
        JobRecords records;
        RunReport report;
        /** The releases that reported their end to the output, per area (MissionSizes). */
        final AtomicIntegerArray releasesEnding = new AtomicIntegerArray(MissionSizes.AREA_COUNT);

        @Override
        public void missionEnded(JobRecords r) {
            records = r;
        }

        @Override
        public void releaseEnding(int area) {
            releasesEnding.incrementAndGet(area);
        }
    }

    static Launch launch(MissionConfiguration c, MissionInput input) {
        Launch l = new Launch();
        l.safelet = new MclSafelet(c, input, l);
        l.report = ScjRuntime.launch(l.safelet, 1);
        return l;
    }

    static MissionConfiguration config(int particles, MclConfig.Memory memory, OverrunPolicy policy, double scale) {
        return new MissionConfiguration(MclConfig.builder().particles(particles).memory(memory).covariance(true).build(),
                policy, scale);
    }

    @BeforeAll
    static void loadClasses() {
        // Class loading allocates; a short mission of each style first keeps it out of the measured ones.
        for (MclConfig.Memory m : new MclConfig.Memory[] {MclConfig.Memory.PREALLOCATED, MclConfig.Memory.SCOPED}) {
            for (OverrunPolicy p : OverrunPolicy.values()) {
                launch(config(16, m, p, 0.2), new SyntheticInput(0.3));
            }
        }
    }

    @ParameterizedTest
    @EnumSource(value = MclConfig.Memory.class, names = {"PREALLOCATED", "SCOPED"})
    void underQueueWithNoOverlapTheEstimatesAreTheIdealRunsBitForBit(MclConfig.Memory memory) {
        MissionConfiguration c = config(64, memory, OverrunPolicy.QUEUE, 1.0);
        Launch l = launch(c, new SyntheticInput(2.0));
        assertTrue(l.report.succeeded(), () -> String.valueOf(l.report.failure()));
        JobRecords r = l.records;
        Timeline t = r.timeline;
        for (int k = 0; k < t.size(); k++) {
            assertTrue(r.completed(k), "queue: event " + k + " " + JobRecords.outcomeName(r.outcome[k]));
            // The comparison needs every job done before the next release (the machine kept up).
            assumeTrue(k + 1 == t.size() || r.endNs[k] <= r.releaseNs[k + 1],
                    "event " + k + " ended after the next release: machine too loaded to compare with the ideal run");
        }
        ImmortalEntry e = l.safelet.entry();
        Localizer ideal = new PreallocatedLocalizer(c.mcl, e.playground, e.startX, e.startY, e.startTheta);
        double[] cov = new double[6];
        for (int k = 0; k < t.size(); k++) {
            int i = t.taskIndex(k);
            if (t.task(k) == Timeline.PREDICT) {
                ideal.predict(e.odoDx[i], e.odoDy[i], e.odoDtheta[i], AbortSignal.NEVER);
            } else {
                ideal.update(e.laserAngle[i], AbortSignal.NEVER);
                ideal.covariance(cov);
                for (int q = 0; q < 6; q++) {
                    assertEquals(Double.doubleToRawLongBits(cov[q]), Double.doubleToRawLongBits(r.cov[6 * k + q]),
                            "covariance of event " + k);
                }
            }
            assertEquals(Double.doubleToRawLongBits(ideal.estimateX()), Double.doubleToRawLongBits(r.estX[k]), "x " + k);
            assertEquals(Double.doubleToRawLongBits(ideal.estimateY()), Double.doubleToRawLongBits(r.estY[k]), "y " + k);
            assertEquals(Double.doubleToRawLongBits(ideal.estimateTheta()), Double.doubleToRawLongBits(r.estTheta[k]),
                    "theta " + k);
        }
    }

    /**
     * Under every policy and style, on a replay fast enough to overlap jobs: every event ends exactly
     * once, and the completed jobs, replayed alone in the order they ran, give the very same estimates
     * (so skipped and terminated events changed nothing on the robot).
     */
    @ParameterizedTest
    @EnumSource(OverrunPolicy.class)
    void everyEventEndsExactlyOnceAndOnlyCompletedJobsChangeTheRobot(OverrunPolicy policy) {
        for (MclConfig.Memory memory : new MclConfig.Memory[] {MclConfig.Memory.PREALLOCATED, MclConfig.Memory.SCOPED}) {
            MissionConfiguration c = config(4000, memory, policy, 0.05);
            Launch l = launch(c, new SyntheticInput(2.0));
            assertTrue(l.report.succeeded(), () -> String.valueOf(l.report.failure()));
            JobRecords r = l.records;
            int n = r.size();
            assertEquals(n, l.safelet.mission().endedEvents(), policy + " " + memory + ": ended events");
            int[] order = new int[n];
            int completed = 0;
            for (int k = 0; k < n; k++) {
                assertNotEquals(JobRecords.PENDING, r.outcome[k], policy + ": event " + k + " never ended");
                if (r.completed(k)) {
                    order[completed++] = k;
                    // Done means ended by the deadline, late after it (whatever the start).
                    assertEquals(r.endNs[k] <= r.deadlineNs[k] ? JobRecords.DONE : JobRecords.LATE, r.outcome[k],
                            policy + " " + memory + ": outcome of event " + k + " against its deadline");
                }
                if (policy == OverrunPolicy.QUEUE) {
                    assertTrue(r.completed(k), "queue processes every event");
                }
                if (policy == OverrunPolicy.SKIP) {
                    assertNotEquals(JobRecords.TERMINATED, r.outcome[k], "skip never aborts");
                }
                // An abort is asked only under terminate, and a job aborted while it ran was asked.
                if (policy != OverrunPolicy.TERMINATE) {
                    assertEquals(-1, r.abortNs[k], policy + ": event " + k + " asked to abort");
                } else if (r.outcome[k] == JobRecords.TERMINATED && r.startNs[k] >= 0) {
                    assertTrue(r.abortFromNs(k) >= r.startNs[k], "event " + k + " aborted unasked");
                    long seen = r.abortSeenFromNs(k);
                    assertTrue(seen >= r.abortFromNs(k) && seen <= r.endNs[k], "event " + k + ": its poll saw the abort at " + seen);
                }
            }
            int dropped = 0;
            for (int k = 0; k < n; k++) {
                dropped += r.completed(k) ? 0 : 1;
            }
            // Without a dropped event the replay below proves nothing about aborted jobs.
            assumeTrue(policy == OverrunPolicy.QUEUE || dropped > 0, policy + ": the machine kept up, nothing dropped");
            // Jobs ran one at a time on the robot: their start order is their order on it.
            sortByStart(order, completed, r);
            ImmortalEntry e = l.safelet.entry();
            Localizer replay = new PreallocatedLocalizer(c.mcl, e.playground, e.startX, e.startY, e.startTheta);
            for (int q = 0; q < completed; q++) {
                int k = order[q];
                int i = r.timeline.taskIndex(k);
                if (r.timeline.task(k) == Timeline.PREDICT) {
                    replay.predict(e.odoDx[i], e.odoDy[i], e.odoDtheta[i], AbortSignal.NEVER);
                } else {
                    replay.update(e.laserAngle[i], AbortSignal.NEVER);
                }
                assertEquals(Double.doubleToRawLongBits(replay.estimateX()), Double.doubleToRawLongBits(r.estX[k]),
                        policy + " " + memory + ": event " + k + " differs from the replay of the completed jobs");
                assertEquals(Double.doubleToRawLongBits(replay.estimateTheta()),
                        Double.doubleToRawLongBits(r.estTheta[k]), policy + " " + memory + ": event " + k);
            }
        }
    }

    /**
     * Terminate stops a periodic job at its task's next release even when no other event is
     * released meanwhile (the predict handler cannot admit its own next release while its job
     * runs): the first predict job here would take 300 ms, the next odometry event comes 50 ms
     * after it, the only laser event at the end.
     */
    @Test
    void terminateStopsAPeriodicJobAtItsTasksNextRelease() {
        MissionConfiguration c = new MissionConfiguration(MclConfig.builder().particles(16).build(),
                OverrunPolicy.TERMINATE, 1.0) {
            @Override
            public Localizer newLocalizer(Playground p, double x, double y, double theta) {
                return new SlowFirstPredict(super.newLocalizer(p, x, y, theta));
            }
        };
        Launch l = launch(c, new OdometryThenOneLaser());
        assertTrue(l.report.succeeded(), () -> String.valueOf(l.report.failure()));
        JobRecords r = l.records;
        assertEquals(JobRecords.TERMINATED, r.outcome[0], "the 300 ms job was not stopped at the next release");
        assertTrue(r.endNs[0] < r.releaseNs[0] + 250_000_000L, "stopped long before its 300 ms: " + r.endNs[0]);
        // its abort was requested at the next release (the timed request; no other event came)
        assertEquals(Math.max(r.releaseNs[1], r.startNs[0]), r.abortFromNs(0), "abort requested at the task's next release");
        assertTrue(r.abortSeenFromNs(0) >= r.abortFromNs(0), "the first poll past that release saw it: " + r.abortSeenFromNs(0));
    }

    /** Ten odometry events 50 ms apart, one laser event after the last but one. */
    private static final class OdometryThenOneLaser extends PlacedMissionInput {
        OdometryThenOneLaser() {
            super(10, 1, Playground.thesis(), 1.5, 1.0, 0.0);
        }

        @Override
        public void readOdometry(double[] time, double[] dx, double[] dy, double[] dtheta) {
            for (int i = 0; i < time.length; i++) {
                time[i] = 0.05 * (i + 1);
                dx[i] = 0.01;
                dtheta[i] = 0.01;
            }
        }

        @Override
        public void readLaser(double[] time, double[] angle) {
            time[0] = 0.475;
            angle[0] = 1.0;
        }
    }

    /** The shipped localizer, whose first predict job first works 300 ms, polling as the MCL loops do. */
    private static final class SlowFirstPredict extends DelegatingLocalizer {
        private boolean first = true;

        SlowFirstPredict(Localizer shipped) {
            super(shipped);
        }

        @Override
        public boolean predict(double dx, double dy, double dtheta, AbortSignal abort) {
            if (first) {
                first = false;
                long end = System.nanoTime() + 300_000_000L;
                while (System.nanoTime() < end) {
                    if (abort.abortRequested()) {
                        return false;
                    }
                }
            }
            return super.predict(dx, dy, dtheta, abort);
        }
    }

    private static void sortByStart(int[] order, int count, JobRecords r) {
        for (int a = 1; a < count; a++) {
            int k = order[a];
            int b = a - 1;
            while (b >= 0 && r.startNs[order[b]] > r.startNs[k]) {
                order[b + 1] = order[b];
                b--;
            }
            order[b + 1] = k;
        }
    }

    @Test
    void preallocatedReleasesAllocateNothing() {
        // HotSpot's one-offs allocate on whichever thread meets them: class initialisation, and a C2
        // compile request, which resolves the compiled class's string constants on the requesting
        // thread (48 B: one String). They can land in any mission, but never twice in the same
        // place; an allocation in our code repeats in every mission. So: some mission of three
        // allocates nothing in any handler's private memory.
        String allocated = null;
        for (int attempt = 0; attempt < 3; attempt++) {
            Launch l = launch(config(500, MclConfig.Memory.PREALLOCATED, OverrunPolicy.QUEUE, 1.0), new SyntheticInput(1.0));
            assertTrue(l.report.succeeded(), () -> String.valueOf(l.report.failure()));
            assumeTrue(l.report.allocationMeasured(), "this JVM does not count allocated bytes");
            allocated = null;
            for (String handler : new String[] {"predict", "update", "sensor"}) {
                AreaUsage a = privateArea(l.report, handler);
                assertTrue(a.cycles() > 0, handler + ": no release measured");
                if (a.totalBytes() != 0 && allocated == null) {
                    allocated = handler + ": releases allocated " + a;
                }
            }
            if (allocated == null) {
                return;
            }
        }
        fail("three missions in a row allocated; the last: " + allocated);
    }

    @Test
    void everyReleaseOfAHandlerReportsItsEndToTheOutputUnderItsOwnArea() {
        // what an SCJ VM that keeps no peak of a private memory measures by (HvmOutput)
        Launch l = launch(config(100, MclConfig.Memory.SCOPED, OverrunPolicy.SKIP, 1.0), new SyntheticInput(1.0));
        assertTrue(l.report.succeeded(), () -> String.valueOf(l.report.failure()));
        assertEquals(0, l.releasesEnding.get(MissionSizes.IMMORTAL));
        assertEquals(0, l.releasesEnding.get(MissionSizes.MISSION));
        for (int area = MissionSizes.PREDICT; area < MissionSizes.AREA_COUNT; area++) {
            String handler = MissionSizes.AREA_NAMES[area];
            long cycles = privateArea(l.report, handler).cycles();
            assertTrue(cycles > 0, handler);
            assertEquals(cycles, l.releasesEnding.get(area), handler + ": releases rtsj-compat counted against those reported");
        }
    }

    @Test
    void scopedTemporariesLandInPrivateMemoryAndTheCommittedSetInMissionMemory() {
        int n = 500;
        Launch pre = launch(config(n, MclConfig.Memory.PREALLOCATED, OverrunPolicy.QUEUE, 1.0), new SyntheticInput(1.0));
        Launch scoped = launch(config(n, MclConfig.Memory.SCOPED, OverrunPolicy.QUEUE, 1.0), new SyntheticInput(1.0));
        assertTrue(scoped.report.succeeded(), () -> String.valueOf(scoped.report.failure()));
        assumeTrue(scoped.report.allocationMeasured(), "this JVM does not count allocated bytes");
        // A predict release allocates three particle arrays, an update release at least five N-sized arrays.
        assertTrue(privateArea(scoped.report, "predict").peakBytes() >= 24L * n, "predict temporaries");
        assertTrue(privateArea(scoped.report, "update").peakBytes() >= 36L * n, "update temporaries");
        // Mission memory holds one particle set instead of two plus the scratch arrays.
        long missionPre = mission(pre.report).peakBytes();
        long missionScoped = mission(scoped.report).peakBytes();
        assertTrue(missionPre - missionScoped >= 30L * n, "mission memory: preallocated " + missionPre
                + " vs scoped " + missionScoped);
    }

    @Test
    void everyAreaFitsItsComputedSizeAndTheSizesAreNotWildGuesses() {
        for (MclConfig.Memory m : new MclConfig.Memory[] {MclConfig.Memory.PREALLOCATED, MclConfig.Memory.SCOPED}) {
            int n = 2000;
            Launch l = launch(config(n, m, OverrunPolicy.QUEUE, 1.0), new SyntheticInput(1.0));
            assertTrue(l.report.succeeded(), () -> String.valueOf(l.report.failure()));
            assumeTrue(l.report.allocationMeasured(), "this JVM does not count allocated bytes");
            for (AreaUsage a : l.report.areas()) {
                assertTrue(a.peakBytes() <= a.size(), a.toString());
            }
            // The particle-dependent part dominates mission memory: the formula must be close to what was used.
            long size = l.safelet.sizes().size(MissionSizes.MISSION);
            long peak = mission(l.report).peakBytes();
            assertTrue(peak >= size - MissionSizes.MISSION_SLACK - 1024, m + ": mission memory " + peak
                    + " is far below the computed " + size);
        }
    }

    @Test
    void theImmortalFormulaCountsEveryArrayTheMissionKeeps() {
        // Immortal memory is arrays sized by the event count E plus about 0.6 KB of objects. A formula
        // that forgot an array misses 4 E bytes or more, which the 16 KiB slack hides from "peak <= size".
        SyntheticInput input = new SyntheticInput(30.0);
        Launch l = launch(config(16, MclConfig.Memory.PREALLOCATED, OverrunPolicy.QUEUE, 0.02), input);
        assertTrue(l.report.succeeded(), () -> String.valueOf(l.report.failure()));
        assumeTrue(l.report.allocationMeasured(), "this JVM does not count allocated bytes");
        long events = input.odometryCount() + input.laserCount();
        long formula = l.safelet.sizes().size(MissionSizes.IMMORTAL) - MissionSizes.IMMORTAL_SLACK;
        long peak = area(l.report, "immortal").peakBytes();
        assertTrue(peak >= formula && peak - formula < 2048, "immortal memory: " + peak + " bytes used, formula "
                + formula + " for " + events + " events");
    }

    @Test
    void anOverflowNamesTheArea() {
        MissionConfiguration c = config(500, MclConfig.Memory.SCOPED, OverrunPolicy.QUEUE, 1.0)
                .areaSize(MissionSizes.UPDATE, 1024);
        Launch l = launch(c, new SyntheticInput(0.5));
        assertTrue(!l.report.succeeded(), "an update release needs far more than 1 KiB in the scoped style");
        assertNotNull(l.report.failure().areaName());
        assertTrue(l.report.failure().areaName().endsWith("update"), l.report.failure().getMessage());
        assertTrue(l.report.failure().bytesNeeded() > 1024);
    }

    @Test
    void aMissionMemoryTooSmallForTheParticlesFailsNamingIt() {
        MissionConfiguration c = config(5000, MclConfig.Memory.PREALLOCATED, OverrunPolicy.QUEUE, 1.0)
                .areaSize(MissionSizes.MISSION, 64 * 1024);
        Launch l = launch(c, new SyntheticInput(0.5));
        assertTrue(!l.report.succeeded());
        assertEquals("MissionMemory", l.report.failure().areaName(), l.report.failure().getMessage());
    }

    static AreaUsage privateArea(RunReport r, String handler) {
        for (AreaUsage a : r.areas()) {
            if (a.name().endsWith(":" + handler)) {
                return a;
            }
        }
        throw new AssertionError("no private memory of " + handler + " in " + r.areas());
    }

    static AreaUsage mission(RunReport r) {
        return area(r, "mission");
    }

    static AreaUsage area(RunReport r, String kind) {
        for (AreaUsage a : r.areas()) {
            if (kind.equals(a.kind())) {
                return a;
            }
        }
        throw new AssertionError("no " + kind + " memory in " + r.areas());
    }
}
