package org.jmclbench.rtsjcompat;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTimeoutPreemptively;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import javax.realtime.PeriodicParameters;
import javax.safetycritical.CyclicExecutive;
import javax.safetycritical.CyclicSchedule;
import javax.safetycritical.Frame;
import javax.safetycritical.Mission;
import javax.safetycritical.PeriodicEventHandler;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;

/** Level 0: the frames of a cyclic schedule run in order at absolute frame times, on one thread. */
class Level0Test {
    private static final long MS = 1_000_000L;

    @AfterEach
    void systemTime() {
        TimeSource.install(new SystemTimeSource());
    }

    private static PeriodicEventHandler handler(String name, List<String> log) {
        PeriodicEventHandler h = new PeriodicEventHandler(Apps.prio(50), new PeriodicParameters(null, Apps.ms(10)),
                Apps.scope(10_000), null, name) {
            @Override
            public void handleAsyncEvent() {
                log.add(name + "@" + TimeSource.current().nanoTime() / MS);
                if (log.size() == 6) {
                    Mission.getMission().requestTermination();
                }
            }
        };
        h.register();
        return h;
    }

    @Test
    void framesRunInOrderAtAbsoluteFrameTimes() {
        TimeSource.install(new VirtualTimeSource(0));
        List<String> log = new ArrayList<>();
        Mission m = new CyclicExecutive() {
            @Override
            protected void initialize() {
                handler("A", log);
                handler("B", log);
            }

            @Override
            public CyclicSchedule getSchedule(PeriodicEventHandler[] hs) {
                return new CyclicSchedule(new Frame[] {
                    new Frame(Apps.ms(10), new PeriodicEventHandler[] {hs[0], hs[1]}),
                    new Frame(Apps.ms(5), new PeriodicEventHandler[] {hs[0]})});
            }

            @Override
            public long missionMemorySize() {
                return 1 << 20;
            }
        };
        RunReport r = assertTimeoutPreemptively(Duration.ofSeconds(60), () -> ScjRuntime.launch(Apps.safelet(1 << 20, m), 0));
        assertTrue(r.succeeded(), () -> String.valueOf(r.failure()));
        assertEquals(Arrays.asList("A@0", "B@0", "A@10", "A@15", "B@15", "A@25"), log);
    }
}
