package org.jmclbench.rtsjcompat;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTimeoutPreemptively;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import javax.realtime.AbsoluteTime;
import javax.realtime.Clock;
import javax.safetycritical.AperiodicEventHandler;
import javax.safetycritical.Mission;
import javax.safetycritical.OneShotEventHandler;
import javax.safetycritical.PeriodicEventHandler;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

/** Periodic, aperiodic and one-shot releases: times, counts, rearming, misses. */
class ReleaseTest {
    private static final Duration HANG = Duration.ofSeconds(60);
    private static final long MS = 1_000_000L;

    @BeforeEach
    void clear() {
        Apps.LOG.clear();
    }

    @AfterEach
    void systemTime() {
        TimeSource.install(new SystemTimeSource());
    }

    private static long now() {
        return TimeSource.current().nanoTime();
    }

    private static RunReport launch(Mission m) {
        RunReport r = assertTimeoutPreemptively(HANG, () -> ScjRuntime.launch(Apps.safelet(1 << 20, m), 1));
        assertTrue(r.succeeded(), () -> String.valueOf(r.failure()));
        return r;
    }

    @Test
    void periodicReleasesAtExactAbsoluteTimesInVirtualTime() {
        TimeSource.install(new VirtualTimeSource(1_000 * MS));
        List<Long> at = new ArrayList<>();
        Mission m = Apps.mission("M", 1 << 20, mission -> Apps.periodic("P", 50, 1 << 16, () -> {
            at.add(now());
            if (at.size() == 5) {
                Mission.getMission().requestTermination();
            }
        }));
        launch(m);
        for (int k = 0; k < 5; k++) {
            assertEquals(at.get(0) + k * 50 * MS, (long) at.get(k), "release " + k);
        }
    }

    @Test
    void periodicReleasesAreNeverEarlyAndDoNotDriftOnRealTime() {
        List<Long> at = new ArrayList<>();
        List<Long> scheduled = new ArrayList<>();
        PeriodicEventHandler[] h = new PeriodicEventHandler[1];
        Mission m = Apps.mission("M", 1 << 20, mission -> h[0] = Apps.periodic("P", 5, 1 << 16, () -> {
            at.add(now());
            AbsoluteTime last = h[0].getLastReleaseTime();
            scheduled.add(last.getMilliseconds() * MS + last.getNanoseconds());
            if (at.size() == 20) {
                Mission.getMission().requestTermination();
            }
        }));
        launch(m);
        long first = scheduled.get(0);
        for (int k = 0; k < 20; k++) {
            // Absolute release times: start + k * period exactly, whatever the lateness before.
            assertEquals(first + k * 5 * MS, (long) scheduled.get(k), "scheduled release " + k);
            assertTrue(at.get(k) >= scheduled.get(k), "release " + k + " started early");
        }
    }

    @Test
    void lateReleasesAndDeadlineMissesAreCounted() {
        TimeSource.install(new VirtualTimeSource(0));
        int[] n = new int[1];
        Mission m = Apps.mission("M", 1 << 20, mission -> Apps.periodic("Slow", 10, 1 << 16, () -> {
            n[0]++;
            if (n[0] == 2) {
                // This release works for 25 ms of virtual time: past its 10 ms deadline, and the
                // releases at 20 and 30 ms can only start after their successors' times.
                TimeSource.current().sleepUntil(ScjThread.self(), now() + 25 * MS);
            }
            if (n[0] == 6) {
                Mission.getMission().requestTermination();
            }
        }));
        RunReport r = launch(m);
        HandlerStats s = r.handler("Slow");
        assertEquals(6, s.completed());
        // The long release (10 ms, ends at 35) and the one it delayed (20 ms, ends at 35 > 30).
        assertEquals(2, s.deadlineMisses());
        assertEquals(1, s.lateReleases(), "the release at 20 ms started at 35 ms, after 30 ms");
    }

    /**
     * A periodic release whose time passed while the previous one ran is run late, not dropped:
     * with 10 ms periods and the release at 10 ms working 25 ms, the releases at 20 and 30 ms
     * both still run (at 35 ms), and the sixth run is the release at 50 ms.
     */
    @Test
    void lateReleasesAreRunNotDropped() {
        TimeSource.install(new VirtualTimeSource(0));
        java.util.List<Long> starts = new java.util.ArrayList<>();
        Mission m = Apps.mission("M", 1 << 20, mission -> Apps.periodic("Slow", 10, 1 << 16, () -> {
            starts.add(now());
            if (starts.size() == 2) {
                TimeSource.current().sleepUntil(ScjThread.self(), now() + 25 * MS);
            }
            if (starts.size() == 6) {
                Mission.getMission().requestTermination();
            }
        }));
        RunReport r = launch(m);
        long t0 = starts.get(0);
        java.util.List<Long> ms = new java.util.ArrayList<>();
        starts.forEach(t -> ms.add((t - t0) / MS));
        assertEquals(java.util.Arrays.asList(0L, 10L, 35L, 35L, 40L, 50L), ms, "start of each release, ms after the first");
        assertEquals(6, r.handler("Slow").completed());
    }

    @Test
    void aperiodicReleasesWhileRunningAreCountedNotLost() throws Exception {
        CountDownLatch firstRunning = new CountDownLatch(1);
        CountDownLatch proceed = new CountDownLatch(1);
        int[] runs = new int[1];
        long[] pendingSeen = {-1};
        AperiodicEventHandler[] a = new AperiodicEventHandler[1];
        Mission m = Apps.mission("M", 1 << 20, mission -> {
            a[0] = Apps.aperiodic("Update", 1 << 16, () -> {
                if (++runs[0] == 1) {
                    firstRunning.countDown();
                    await(proceed);
                }
                if (runs[0] == 6) {
                    Mission.getMission().requestTermination();
                }
            });
            boolean[] done = new boolean[1];
            Apps.periodic("Sensor", 2, 1 << 16, () -> {
                if (done[0]) {
                    return;
                }
                done[0] = true;
                a[0].release();
                await(firstRunning);
                for (int i = 0; i < 5; i++) {
                    a[0].release();
                }
                pendingSeen[0] = ScjRuntime.stats(a[0]).pending();
                proceed.countDown();
            });
        });
        RunReport r = launch(m);
        assertEquals(5, pendingSeen[0], "five releases pending while the first runs");
        HandlerStats s = r.handler("Update");
        assertEquals(6, runs[0]);
        assertEquals(6, s.releases());
        assertEquals(6, s.completed());
        assertEquals(0, s.pending());
    }

    private static void await(CountDownLatch l) {
        try {
            assertTrue(l.await(30, TimeUnit.SECONDS), "hang guard");
        } catch (InterruptedException e) {
            throw new AssertionError(e);
        }
    }

    @Test
    void oneShotIsRearmedRelativeAndAbsoluteAndDescheduled() {
        TimeSource.install(new VirtualTimeSource(0));
        List<Long> at = new ArrayList<>();
        boolean[] answers = new boolean[3];
        Object[] next = new Object[1];
        Mission m = Apps.mission("M", 1 << 20, mission -> Apps.oneShot("Laser", 10, h -> {
            at.add(now());
            if (at.size() == 1) {
                h.scheduleNextReleaseTime(Apps.ms(5));
            } else if (at.size() == 2) {
                AbsoluteTime t = Clock.getRealtimeClock().getTime(new AbsoluteTime());
                h.scheduleNextReleaseTime(t.add(7, 0));
            } else {
                answers[0] = h.deschedule();
                h.scheduleNextReleaseTime(Apps.ms(1000));
                answers[1] = h.deschedule();
                next[0] = h.getNextReleaseTime(null);
                answers[2] = h.deschedule();
                Mission.getMission().requestTermination();
            }
        }));
        RunReport r = launch(m);
        long start = at.get(0) - 10 * MS;
        assertEquals(start + 15 * MS, (long) at.get(1), "relative rearm: 5 ms after the release");
        assertEquals(start + 22 * MS, (long) at.get(2), "absolute rearm: 7 ms after the second");
        assertFalse(answers[0], "nothing scheduled during the release");
        assertTrue(answers[1], "the rearmed release was cancelled");
        assertNull(next[0]);
        assertFalse(answers[2]);
        assertEquals(3, r.handler("Laser").completed());
    }

    @Test
    void aOneShotRescheduledFromAnotherHandlerSleepsToTheNewTime() {
        TimeSource.install(new VirtualTimeSource(0));
        List<Long> at = new ArrayList<>();
        OneShotEventHandler[] o = new OneShotEventHandler[1];
        Mission m = Apps.mission("M", 1 << 20, mission -> {
            o[0] = Apps.oneShot("Late", 1000, h -> {
                at.add(now());
                Mission.getMission().requestTermination();
            });
            boolean[] done = new boolean[1];
            Apps.periodic("Early", 3, 1 << 16, () -> {
                if (!done[0]) {
                    done[0] = true;
                    at.add(now());
                    o[0].scheduleNextReleaseTime(Apps.ms(4));
                }
            });
        });
        launch(m);
        assertEquals(2, at.size(), "one release, not the one at 1000 ms");
        assertEquals(at.get(0) + 4 * MS, (long) at.get(1), "released 4 ms after the rearm");
    }
}
