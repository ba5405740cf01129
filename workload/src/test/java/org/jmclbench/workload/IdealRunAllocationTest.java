package org.jmclbench.workload;

import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.File;
import java.lang.management.ManagementFactory;

import org.jmclbench.workload.data.Dataset;
import org.jmclbench.workload.data.DatasetReader;
import org.jmclbench.core.timeline.Timeline;
import org.jmclbench.core.mcl.Localizer;
import org.jmclbench.workload.mcl.Localizers;
import org.jmclbench.core.mcl.MclConfig;
import org.jmclbench.core.record.JobRecords;
import org.jmclbench.workload.release.ThreadCpuClock;
import org.jmclbench.workload.testing.SyntheticDataset;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The measured window allocates nothing in the preallocated style: the ideal run's loop,
 * predict, update and the recording of estimates, measured with the thread's allocation
 * counter (HotSpot's com.sun.management.ThreadMXBean).
 */
class IdealRunAllocationTest {
    @TempDir
    File tmp;

    private static long allocated(com.sun.management.ThreadMXBean bean) {
        return bean.getThreadAllocatedBytes(Thread.currentThread().getId());
    }

    private long measure(MclConfig c, Dataset d, Timeline t) {
        java.lang.management.ThreadMXBean plain = ManagementFactory.getThreadMXBean();
        assumeTrue(plain instanceof com.sun.management.ThreadMXBean, "no allocation counter on this JVM");
        com.sun.management.ThreadMXBean bean = (com.sun.management.ThreadMXBean) plain;
        assumeTrue(bean.isThreadAllocatedMemorySupported() && bean.isThreadAllocatedMemoryEnabled());
        JobRecords records = new JobRecords(t, c.covariance);
        // Warm: the first run loads and initialises classes (which allocates, once).
        IdealRun.run(d, t, Localizers.create(c, d.playground, d.startX, d.startY, d.startTheta), records,
                ThreadCpuClock.probe());
        Localizer l = Localizers.create(c, d.playground, d.startX, d.startY, d.startTheta);
        IdealRun run = new IdealRun(d, t, l, records, ThreadCpuClock.probe());
        long overhead = -allocated(bean) + allocated(bean);
        long before = allocated(bean);
        run.run();
        long after = allocated(bean);
        return after - before - Math.max(0, overhead);
    }

    @Test
    void thePreallocatedStyleAllocatesNothingWhileRunning() throws Exception {
        Dataset d = DatasetReader.readFolder(SyntheticDataset.write(new File(tmp, "d"), 5.0, 1, true, true));
        Timeline t = d.timeline();
        for (MclConfig.Resample r : MclConfig.Resample.values()) {
            for (MclConfig.Estimate e : MclConfig.Estimate.values()) {
                MclConfig c = MclConfig.builder().particles(500).resample(r).estimate(e).covariance(true).build();
                long bytes = measure(c, d, t);
                // Small constant slack for the counter itself; a single allocation per job would be >= 16 x events.
                assertTrue(bytes < 256, c + ": " + bytes + " bytes allocated during " + t.size() + " jobs");
            }
        }
    }

    @Test
    void theAllocatingStyleDoesAllocate() throws Exception {
        Dataset d = DatasetReader.readFolder(SyntheticDataset.write(new File(tmp, "d"), 2.0, 1, true, true));
        Timeline t = d.timeline();
        long bytes = measure(MclConfig.builder().particles(500).memory(MclConfig.Memory.ALLOCATING).build(), d, t);
        // At least one particle object (>= 16 bytes) per particle per job.
        assertTrue(bytes > 16L * 500 * t.size(), bytes + " bytes");
    }
}
