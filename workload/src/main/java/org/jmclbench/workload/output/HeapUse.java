package org.jmclbench.workload.output;

import java.lang.management.ManagementFactory;
import java.lang.management.MemoryPoolMXBean;
import java.lang.management.MemoryType;

import org.jmclbench.core.record.JobRecords;

/**
 * The one memory area of the engines that run on the heap (javase, rtsj and the ideal run): its
 * maximum size, the peak used over the run (the heap pools' peaks, reset when the run begins)
 * and bytes allocated per release.
 */
public final class HeapUse {
    private HeapUse() {
    }

    /** Resets the heap pools' peaks: call right before the run. */
    public static HeapUse begin() {
        for (MemoryPoolMXBean p : ManagementFactory.getMemoryPoolMXBeans()) {
            if (p.getType() == MemoryType.HEAP && p.isValid()) {
                p.resetPeakUsage();
            }
        }
        return new HeapUse();
    }

    /**
     * The heap area after the run.
     *
     * @param allocatedBytes bytes the engine's threads allocated in the measured window, or null (unknown, ideal runs)
     * @param records        the run's jobs: those started share the allocation (a dropped job never ran)
     */
    public MemoryArea end(Long allocatedBytes, JobRecords records) {
        int releases = 0;
        for (int k = 0; k < records.size(); k++) {
            if (records.startNs[k] >= 0) {
                releases++;
            }
        }
        long peak = 0;
        for (MemoryPoolMXBean p : ManagementFactory.getMemoryPoolMXBeans()) {
            if (p.getType() == MemoryType.HEAP && p.isValid() && p.getPeakUsage() != null) {
                peak += p.getPeakUsage().getUsed();
            }
        }
        Long perRelease = allocatedBytes == null || allocatedBytes < 0 || releases == 0
                ? null : Math.round((double) allocatedBytes / releases);
        return new MemoryArea("heap", Runtime.getRuntime().maxMemory(), peak, perRelease);
    }
}
