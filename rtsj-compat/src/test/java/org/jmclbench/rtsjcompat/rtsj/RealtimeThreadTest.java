package org.jmclbench.rtsjcompat.rtsj;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import javax.realtime.AbsoluteTime;
import javax.realtime.Clock;
import javax.realtime.PeriodicParameters;
import javax.realtime.PriorityParameters;
import javax.realtime.RealtimeThread;
import javax.realtime.RelativeTime;
import org.jmclbench.rtsjcompat.SystemTimeSource;
import org.jmclbench.rtsjcompat.TimeSource;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

/** Sleeps to absolute and relative times and periodic releases: never early, misses reported; nothing asserts a duration. */
class RealtimeThreadTest {
    static volatile long sink;

    @BeforeEach
    void systemTime() {
        TimeSource.install(new SystemTimeSource());
    }

    private static long now() {
        AbsoluteTime t = Clock.getRealtimeClock().getTime();
        return t.getMilliseconds() * 1000000L + t.getNanoseconds();
    }

    @Test
    void sleepToAnAbsoluteTimeNeverReturnsBeforeIt() {
        OnRealtimeThread.run(self -> {
            for (int i = 0; i < 5; i++) {
                AbsoluteTime t = Clock.getRealtimeClock().getTime().add(2, 500000);
                RealtimeThread.sleep(t);
                AbsoluteTime after = Clock.getRealtimeClock().getTime();
                assertTrue(after.compareTo(t) >= 0, after + " before " + t);
            }
            long before = now();
            RealtimeThread.sleep(new RelativeTime(3, 0));
            assertTrue(now() - before >= 3000000L);
        });
    }

    @Test
    void anInterruptEndsASleepWithInterruptedException() {
        OnRealtimeThread.run(self -> {
            self.interrupt();
            assertThrows(InterruptedException.class,
                    () -> RealtimeThread.sleep(Clock.getRealtimeClock().getTime().add(60000, 0)));
        });
    }

    @Test
    void periodicReleasesComeAtStartPlusKPeriodsAndAMissIsReported() throws Exception {
        long periodNs = 5000000L;
        long[] returns = new long[4];
        boolean[] answers = new boolean[4];
        long[] started = new long[1];
        RealtimeThread t = new RealtimeThread(new PriorityParameters(30),
                new PeriodicParameters(new RelativeTime(0, 0), new RelativeTime(5, 0))) {
            @Override
            public void run() {
                started[0] = now();
                for (int k = 0; k < 3; k++) {
                    answers[k] = waitForNextPeriod();
                    returns[k] = now();
                }
                // overrun the current release's deadline (the period): the next call reports it
                long until = returns[2] + 2 * periodNs;
                while (now() < until) {
                    sink++;
                }
                answers[3] = waitForNextPeriod();
                returns[3] = now();
            }
        };
        long beforeStart = now();
        t.start();
        t.join(60000);
        assertFalse(t.isAlive());
        for (int k = 0; k < 3; k++) {
            assertTrue(returns[k] >= beforeStart + (k + 1) * periodNs, "release " + (k + 1) + " early");
        }
        assertFalse(answers[3], "the overrun release missed its deadline");
        assertTrue(started[0] >= beforeStart);
    }

    @Test
    void waitForNextPeriodNeedsPeriodicParameters() {
        OnRealtimeThread.run(self -> assertThrows(IllegalThreadStateException.class, self::waitForNextPeriod));
    }

    @Test
    void priorityParametersMapOntoJavaPrioritiesInOrder() {
        RealtimeThread low = new RealtimeThread(new PriorityParameters(10));
        RealtimeThread high = new RealtimeThread(new PriorityParameters(90));
        assertTrue(low.getPriority() < high.getPriority());
        high.setSchedulingParameters(new PriorityParameters(1));
        assertEquals(Thread.MIN_PRIORITY, high.getPriority());
    }
}
