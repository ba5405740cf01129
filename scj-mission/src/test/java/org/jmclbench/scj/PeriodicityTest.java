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
    void oneEventHasTheDefaultPeriod() {
        assertEquals(Periodicity.DEFAULT_PERIOD_S, Periodicity.period(new double[] {0.05}), 0.0);
        assertEquals(-1, Periodicity.firstIrregular(new double[] {0.05}));
    }
}
