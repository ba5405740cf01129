package org.jmclbench.scj;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;

class PeriodicityTest {
    @Test
    void regularOdometryHasItsMeanIntervalAsPeriod() {
        double[] t = {0.05, 0.1, 0.15000000000000002, 0.2};
        assertEquals(0.05, Periodicity.period(t), 1e-12);
        assertEquals(-1, Periodicity.firstIrregular(t));
    }

    @Test
    void theFirstIntervalOffByMoreThanTheToleranceIsNamed() {
        double[] t = {0.05, 0.1, 0.15, 0.21, 0.25, 0.3};
        assertEquals(3, Periodicity.firstIrregular(t));
    }

    @Test
    void intervalsEachWithinTheToleranceButDriftingTogetherAreNotPeriodic() {
        // five intervals of 50.8 ms, then five of 49.2 ms: the mean is 50 ms and each interval is
        // 0.8 ms off it, but reading 2 is logged 1.6 ms after its periodic release
        double[] t = new double[11];
        t[0] = 0.05;
        for (int i = 1; i < t.length; i++) {
            t[i] = t[i - 1] + (i <= 5 ? 0.0508 : 0.0492);
        }
        assertEquals(0.05, Periodicity.period(t), 1e-12);
        assertEquals(0.15, Periodicity.periodicRelease(t, 2), 1e-12);
        assertEquals(2, Periodicity.firstIrregular(t));
    }

    @Test
    void oneEventHasTheDefaultPeriod() {
        assertEquals(Periodicity.DEFAULT_PERIOD_S, Periodicity.period(new double[] {0.05}), 0.0);
        assertEquals(-1, Periodicity.firstIrregular(new double[] {0.05}));
    }
}
