package org.jmclbench.rtsjcompat;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTimeoutPreemptively;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import javax.safetycritical.AperiodicEventHandler;
import javax.safetycritical.LaunchLevel1;
import javax.safetycritical.Mission;
import javax.safetycritical.OneShotEventHandler;
import javax.safetycritical.Services;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

/** Phases in order, in the right areas; termination ends every kind of handler; the sequence ends. */
class MissionLifecycleTest {
    // A guard against a hang of the layer, not a timing assertion.
    private static final Duration HANG = Duration.ofSeconds(60);

    @BeforeEach
    void reset() {
        TimeSource.install(new SystemTimeSource());
        Apps.LOG.clear();
    }

    @Test
    void phasesRunInOrderInTheirAreasAndTheLinearSequenceStops() {
        int[] releases = new int[2];
        Mission a = Apps.mission("A", 1_000_000, m -> Apps.periodic("PA", 2, 10_000, () -> {
            Apps.log("PA release in " + Services.getNameOfCurrentMemoryArea());
            if (++releases[0] == 3) {
                Mission.getMission().requestTermination();
            }
        }));
        Mission b = Apps.mission("B", 1_000_000, m -> Apps.periodic("PB", 2, 10_000, () -> {
            if (++releases[1] == 2) {
                Mission.getMission().requestTermination();
            }
        }));
        RunReport r = assertTimeoutPreemptively(HANG, () -> ScjRuntime.launch(Apps.safelet(100_000, a, b), 1));
        assertTrue(r.succeeded(), () -> String.valueOf(r.failure()));
        List<String> expected = Arrays.asList(
                "initializeApplication in ImmortalMemory",
                "getSequencer in ImmortalMemory",
                "A.initialize in MissionMemory",
                "PA release in PrivateMemory:PA",
                "PA release in PrivateMemory:PA",
                "PA release in PrivateMemory:PA",
                "PA.cleanUp",
                "A.cleanUp in MissionMemory",
                "B.initialize in MissionMemory",
                "PB.cleanUp",
                "B.cleanUp in MissionMemory",
                "Safelet.cleanUp in ImmortalMemory");
        assertEquals(expected, new ArrayList<>(Apps.LOG));
        assertEquals(3, r.handler("PA").completed());
        assertEquals(2, r.handler("PB").completed());
        assertEquals(2, r.area("MissionMemory").cycles(), "mission memory emptied after each mission");
    }

    @Test
    void terminationEndsPeriodicAperiodicAndOneShotHandlers() {
        Mission m = Apps.mission("M", 1_000_000, mission -> {
            AperiodicEventHandler idle = Apps.aperiodic("Idle", 10_000, () -> Apps.log("Idle released"));
            OneShotEventHandler far = Apps.oneShot("Far", 3_600_000, h -> Apps.log("Far released"));
            int[] n = new int[1];
            Apps.periodic("Tick", 2, 10_000, () -> {
                if (++n[0] == 2) {
                    Mission.getMission().requestTermination();
                }
            });
        });
        RunReport r = assertTimeoutPreemptively(HANG, () -> ScjRuntime.launch(Apps.safelet(100_000, m), 1));
        assertTrue(r.succeeded(), () -> String.valueOf(r.failure()));
        assertTrue(Apps.LOG.contains("Idle.cleanUp"));
        assertTrue(Apps.LOG.contains("Far.cleanUp"));
        assertTrue(!Apps.LOG.contains("Idle released") && !Apps.LOG.contains("Far released"));
        assertEquals("Safelet.cleanUp in ImmortalMemory", Apps.LOG.get(Apps.LOG.size() - 1));
        for (Thread t : Thread.getAllStackTraces().keySet()) {
            assertTrue(!(t instanceof ScjThread) || !t.isAlive() || t.getState() == Thread.State.TERMINATED,
                    () -> "SCJ thread still alive: " + t.getName());
        }
    }

    @Test
    void aFailingHandlerFailsTheLaunchAndStillCleansUp() {
        Mission m = Apps.mission("M", 1_000_000, mission -> Apps.periodic("Bad", 2, 10_000, () -> {
            throw new IllegalStateException("boom");
        }));
        MissionFailure f = assertTimeoutPreemptively(HANG, () -> {
            try {
                new LaunchLevel1(Apps.safelet(100_000, m));
                return null;
            } catch (MissionFailure e) {
                return e;
            }
        });
        assertTrue(f != null && f.where().equals("Bad") && f.getMessage().contains("boom"), String.valueOf(f));
        assertTrue(Apps.LOG.contains("M.cleanUp in MissionMemory"));
        assertTrue(Apps.LOG.contains("Safelet.cleanUp in ImmortalMemory"));
        assertEquals(f, ScjRuntime.lastReport().failure());
    }

    @Test
    void requestTerminationReportsWhetherItWasAlreadyRequested() {
        boolean[] answers = new boolean[2];
        Mission m = Apps.mission("M", 1_000_000, mission -> Apps.periodic("P", 2, 10_000, () -> {
            answers[0] = Mission.getMission().requestTermination();
            answers[1] = Mission.getMission().requestTermination();
        }));
        RunReport r = assertTimeoutPreemptively(HANG, () -> ScjRuntime.launch(Apps.safelet(100_000, m), 1));
        assertTrue(r.succeeded());
        assertEquals(false, answers[0], "the first call initiates termination");
        assertEquals(true, answers[1], "the second finds it requested");
    }
}
