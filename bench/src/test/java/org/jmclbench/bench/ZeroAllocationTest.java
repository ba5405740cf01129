package org.jmclbench.bench;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.File;
import org.jmclbench.workload.data.Dataset;
import org.jmclbench.workload.data.DatasetReader;
import org.jmclbench.core.mcl.MclConfig;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;

/**
 * SPEC 11's "zero bytes allocated per job in the preallocated style once warm", counted
 * exactly by the JVM's per-thread allocation counter (not timed, so it cannot flake); the
 * allocating style is the control that shows the counter sees allocations.
 */
class ZeroAllocationTest {
    private static Dataset dataset() throws Exception {
        File dir = new File("").getAbsoluteFile();
        while (dir != null && !new File(dir, "data/match-short/odometry.txt").isFile()) {
            dir = dir.getParentFile();
        }
        assertTrue(dir != null, "data/match-short not found");
        return DatasetReader.readFolder(new File(dir, "data/match-short"));
    }

    @Test
    void preallocatedJobsAllocateNothingOnceWarm() throws Exception {
        Dataset d = dataset();
        double control = AllocationCheck.bytesPerJob(d, 200, MclConfig.Memory.ALLOCATING, false);
        Assumptions.assumeFalse(Double.isNaN(control), "this JVM has no per-thread allocation counter");
        assertTrue(control >= 200 * 16, "the counter misses the allocating style's particles: " + control);
        assertEquals(0.0, AllocationCheck.bytesPerJob(d, 200, MclConfig.Memory.PREALLOCATED, false), "predict");
        assertEquals(0.0, AllocationCheck.bytesPerJob(d, 200, MclConfig.Memory.PREALLOCATED, true), "update");
    }
}
