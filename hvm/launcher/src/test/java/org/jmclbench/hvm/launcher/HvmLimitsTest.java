package org.jmclbench.hvm.launcher;

import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.jmclbench.core.mcl.MclConfig;
import org.junit.jupiter.api.Test;

/**
 * The HVM's limits at their boundaries, which were measured on the VM (docs/HVM.md): 65,535
 * particles run and 65,536 crash; the scoped style is right at 8,191 and wrong at 8,192.
 */
class HvmLimitsTest {

    private static MclConfig filter(int particles, MclConfig.Memory memory, boolean covariance) {
        return MclConfig.builder().particles(particles).memory(memory).covariance(covariance).build();
    }

    @Test
    void theLastCountThatRanIsAllowedAndTheFirstThatFailedIsNot() {
        assertNull(HvmLimits.beyond(filter(65_535, MclConfig.Memory.PREALLOCATED, false), 574));
        assertTrue(HvmLimits.beyond(filter(65_536, MclConfig.Memory.PREALLOCATED, false), 574)
                .startsWith("--particles 65536: the HVM holds at most 65,535 particles"));
        assertNull(HvmLimits.beyond(filter(8_191, MclConfig.Memory.SCOPED, false), 574));
        assertTrue(HvmLimits.beyond(filter(8_192, MclConfig.Memory.SCOPED, false), 574)
                .startsWith("--particles 8192: the HVM runs the scoped memory style with at most 8,191 particles"));
    }

    @Test
    void aDatasetWhoseRecordsOutgrowTheArraysIsNamedWithTheOptionThatGrowsThem() {
        MclConfig plain = filter(400, MclConfig.Memory.PREALLOCATED, false);
        assertNull(HvmLimits.beyond(plain, 65_535));
        assertTrue(HvmLimits.beyond(plain, 65_536).startsWith("the dataset's 65,536 events"));
        MclConfig covariance = filter(400, MclConfig.Memory.PREALLOCATED, true);
        assertNull(HvmLimits.beyond(covariance, 10_922));
        assertTrue(HvmLimits.beyond(covariance, 10_923).startsWith("-c: the covariance of the dataset's 10,923 events"));
    }
}
