package org.jmclbench.rtsjcompat;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTimeoutPreemptively;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.time.Duration;
import javax.safetycritical.ManagedMemory;
import javax.safetycritical.Mission;
import javax.safetycritical.Services;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

/** Memory areas as budgets: charged where allocated, peaks reported, overflow fails naming the area. */
class MemoryAreaTest {
    private static final Duration HANG = Duration.ofSeconds(60);
    /** Slack for what the accounting cannot attribute exactly (a reading's own cost, alignment). */
    private static final long SLACK = 512;
    static volatile Object sink;

    @BeforeAll
    static void measured() {
        assumeTrue(AllocationMeter.current().measures(), "this JVM has no per-thread allocation counter");
    }

    @BeforeEach
    void systemTime() {
        TimeSource.install(new SystemTimeSource());
        Apps.LOG.clear();
    }

    private static RunReport launch(long immortal, Mission m) {
        return assertTimeoutPreemptively(HANG, () -> ScjRuntime.launch(Apps.safelet(immortal, m), 1));
    }

    /** A mission of one periodic handler running {@code body} {@code releases} times (after a warm-up release). */
    private static Mission oneHandler(long missionSize, long privateSize, int releases, Runnable body) {
        return Apps.mission("M", missionSize, mission -> {
            int[] n = new int[1];
            Apps.periodic("H", 1, privateSize, () -> {
                body.run();
                if (++n[0] == releases) {
                    Mission.getMission().requestTermination();
                }
            });
        });
    }

    @Test
    void aPrivateMemoryOverflowFailsTheRunNamingTheAreaAndTheBytes() {
        RunReport r = launch(1 << 20, oneHandler(1 << 20, 1000, 3, () -> sink = new byte[4000]));
        assertFalse(r.succeeded());
        MissionFailure f = r.failure();
        assertEquals("PrivateMemory:H", f.areaName());
        assertTrue(f.bytesNeeded() >= 4000, f.getMessage());
        assertTrue(f.getCause() instanceof OutOfMemoryError);
        assertTrue(f.getMessage().contains("PrivateMemory:H overflowed: needed"), f.getMessage());
        assertTrue(Apps.LOG.contains("Safelet.cleanUp in ImmortalMemory"), "cleanup still runs");
    }

    @Test
    void aMissionMemoryOverflowInInitializeFailsNamingMissionMemory() {
        Mission m = Apps.mission("M", 10_000, mission -> sink = new long[5000]);
        RunReport r = launch(1 << 20, m);
        assertEquals("MissionMemory", r.failure().areaName());
        assertTrue(r.failure().bytesNeeded() >= 40_000);
    }

    @Test
    void eachReleaseIsChargedToItsPrivateMemoryAndThePeakIsOneRelease() {
        RunReport r = launch(1 << 20, oneHandler(1 << 20, 100_000, 10, () -> sink = new byte[4000]));
        assertTrue(r.succeeded(), () -> String.valueOf(r.failure()));
        AreaUsage p = r.area("PrivateMemory:H");
        assertEquals(100_000, p.size());
        assertEquals(10, p.cycles(), "emptied once per release");
        // The first release also pays for loading the classes it touches: look at the peak of one
        // release against ten releases' total.
        assertTrue(p.peakBytes() >= 4000, p.toString());
        assertTrue(p.totalBytes() >= 10 * 4000, p.toString());
        assertTrue(p.peakBytes() < p.totalBytes() / 2, "the peak is one release, not the sum: " + p);
    }

    @Test
    void theReleasesThatAllocatedAreCountedApartFromThoseThatDidNot() {
        int[] n = new int[1];
        RunReport r = launch(1 << 20, oneHandler(1 << 20, 100_000, 12, () -> {
            if (n[0] == 3 || n[0] == 7) {
                sink = new byte[4000];
            }
            n[0]++;
        }));
        assertTrue(r.succeeded(), () -> String.valueOf(r.failure()));
        AreaUsage p = r.area("PrivateMemory:H");
        assertEquals(12, p.cycles());
        // releases 4 and 8 allocated; the first may also have (loading the classes it touches)
        assertTrue(p.allocatingCycles() >= 2 && p.allocatingCycles() <= 3, p.toString());
        assertTrue(p.peakBytes() >= 4000, p.toString());
    }

    @Test
    void initializeIsChargedToMissionMemoryAndNestedAndOuterAllocationsToTheirAreas() {
        Mission m = Apps.mission("M", 1 << 20, mission -> {
            sink = new byte[50_000];
            int[] n = new int[1];
            Apps.periodic("H", 1, 100_000, () -> {
                ManagedMemory.enterPrivateMemory(20_000, () -> {
                    Apps.log("nested in " + Services.getNameOfCurrentMemoryArea());
                    sink = new byte[8000];
                });
                ManagedMemory.executeInOuterArea(() -> sink = new byte[3000]);
                if (++n[0] == 3) {
                    Mission.getMission().requestTermination();
                }
            });
        });
        RunReport r = launch(1 << 20, m);
        assertTrue(r.succeeded(), () -> String.valueOf(r.failure()));
        assertTrue(Apps.LOG.contains("nested in PrivateMemory:H/nested"));
        AreaUsage mission = r.area("MissionMemory");
        assertTrue(mission.peakBytes() >= 50_000 + 3 * 3000, mission.toString());
        AreaUsage nested = r.area("PrivateMemory:H/nested");
        assertEquals(3, nested.depth());
        assertTrue(nested.peakBytes() >= 8000 && nested.totalBytes() >= 3 * 8000, nested.toString());
        AreaUsage priv = r.area("PrivateMemory:H");
        assertTrue(priv.totalBytes() < 3 * 8000, "nested and outer allocations are not the private area's: " + priv);
    }

    @Test
    void aReleaseThatAllocatesNothingIsChargedNothingOnceWarm() {
        long[] acc = new long[1];
        int[] n = new int[1];
        Mission m = Apps.mission("M", 1 << 20, mission -> Apps.periodic("Quiet", 1, 10_000, () -> {
            for (int i = 0; i < 1000; i++) {
                acc[0] += i * 31L;
            }
            if (++n[0] == 50) {
                Mission.getMission().requestTermination();
            }
        }));
        RunReport r = launch(1 << 20, m);
        assertTrue(r.succeeded(), () -> String.valueOf(r.failure()));
        AreaUsage p = r.area("PrivateMemory:Quiet");
        // The first release may load classes; the other 49 together stay within the slack.
        assertTrue(p.totalBytes() - p.peakBytes() <= SLACK, p.toString());
    }

    @Test
    void areasAreReportedWithNamesSizesAndLifetimeOrder() {
        RunReport r = launch(300_000, oneHandler(200_000, 50_000, 2, () -> { }));
        assertTrue(r.succeeded(), () -> String.valueOf(r.failure()));
        assertEquals("ImmortalMemory", r.areas().get(0).name());
        assertEquals(300_000, r.area("ImmortalMemory").size());
        assertEquals(0, r.area("ImmortalMemory").depth());
        assertEquals(200_000, r.area("MissionMemory").size());
        assertEquals(1, r.area("MissionMemory").depth());
        assertEquals(50_000, r.area("PrivateMemory:H").size());
        assertEquals(2, r.area("PrivateMemory:H").depth());
        assertTrue(r.allocationMeasured());
    }

    @Test
    void aWarmUpLaunchMeasuresOverflowsWithoutFailing() {
        RunReport warm = assertTimeoutPreemptively(HANG,
                () -> ScjRuntime.warmUp(Apps.safelet(1 << 20, oneHandler(1 << 20, 1000, 3, () -> sink = new byte[4000])), 1));
        assertTrue(warm.succeeded(), () -> String.valueOf(warm.failure()));
        assertFalse(warm.budgetsEnforced());
        assertTrue(warm.area("PrivateMemory:H").peakBytes() >= 4000);
        RunReport next = launch(1 << 20, oneHandler(1 << 20, 1000, 3, () -> sink = new byte[4000]));
        assertTrue(next.budgetsEnforced() && !next.succeeded(), "the next launch enforces again");
    }

    @Test
    void theApiAReleaseUsesAllocatesNothing() {
        int[] n = new int[1];
        Mission m = Apps.mission("M", 1 << 20, mission -> {
            javax.realtime.AbsoluteTime now = new javax.realtime.AbsoluteTime();
            javax.realtime.AbsoluteTime next = new javax.realtime.AbsoluteTime();
            javax.realtime.RelativeTime later = Apps.ms(1000);
            javax.safetycritical.AperiodicEventHandler a = Apps.aperiodic("A", 10_000, () -> { });
            javax.safetycritical.OneShotEventHandler o = Apps.oneShot("O", 1000, h -> { });
            Apps.periodic("User", 1, 10_000, () -> {
                javax.realtime.Clock.getRealtimeClock().getTime(now);
                now.add(later, next);
                a.release();
                o.scheduleNextReleaseTime(next);
                o.getNextReleaseTime(next);
                if (++n[0] == 50) {
                    Mission.getMission().requestTermination();
                }
            });
        });
        RunReport r = launch(1 << 20, m);
        assertTrue(r.succeeded(), () -> String.valueOf(r.failure()));
        for (String area : new String[] {"PrivateMemory:User", "PrivateMemory:A"}) {
            AreaUsage p = r.area(area);
            // The first release may load classes; all the others together stay within the slack.
            assertTrue(p.totalBytes() - p.peakBytes() <= SLACK, p.toString());
        }
        assertTrue(r.handler("A").completed() >= 1, r.handler("A").toString());
    }
}
