package org.jmclbench.hvm;

import javax.realtime.MemoryArea;

import org.jmclbench.core.record.JobRecords;
import org.jmclbench.scj.MissionOutput;
import org.jmclbench.scj.MissionRunFile;
import org.jmclbench.scj.MissionSizes;

import vm.Memory;

/**
 * The mission's output on the HVM: the job records, written to the result file by the natives,
 * and the use of each handler's private memory, measured at the end of each release (icecap
 * empties a private memory after each release and keeps no peak of it).
 */
final class HvmOutput implements MissionOutput {
    private boolean written;
    // per area (MissionSizes), only the private memories' entries used; built before the mission
    private final long[] largestRelease = new long[MissionSizes.AREA_COUNT];
    private final long[] releases = new long[MissionSizes.AREA_COUNT];
    private final long[] allocatingReleases = new long[MissionSizes.AREA_COUNT];
    private final long[] allocatedBytes = new long[MissionSizes.AREA_COUNT];

    @Override
    public void releaseEnding(int area) {
        // the handler's private memory is current, and holds what this release allocated
        long used = Memory.getCurrentMemoryArea().consumedMemory();
        releases[area]++;
        if (used > 0) {
            allocatingReleases[area]++;
            allocatedBytes[area] += used;
        }
        if (used > largestRelease[area]) {
            largestRelease[area] = used;
        }
    }

    @Override
    public void missionEnded(JobRecords r) {
        int n = r.size();
        HvmData.put(MissionRunFile.OUTPUT_MAGIC);
        HvmData.put(MissionRunFile.VERSION);
        HvmData.put(n);
        HvmData.put(r.cov != null ? 1 : 0);
        putLongs(r.releaseNs, n);
        putLongs(r.startNs, n);
        putLongs(r.endNs, n);
        putLongs(r.deadlineNs, n);
        putLongs(r.wakeNs, n);
        for (int k = 0; k < n; k++) {
            HvmData.put(r.outcome[k]);
        }
        HvmData.put(MissionRunFile.ABORT_SECTION);
        putLongs(r.abortNs, n);
        putLongs(r.abortSeenNs, n);
        putReals(r.estX, n);
        putReals(r.estY, n);
        putReals(r.estTheta, n);
        if (r.cov != null) {
            putReals(r.cov, r.cov.length);
        }
        HvmData.putReal(r.initialX);
        HvmData.putReal(r.initialY);
        HvmData.putReal(r.initialTheta);
        HvmData.put(r.durationNs);
        // Each area's use, in the order of MissionSizes.AREA_NAMES. The mission ends here, in
        // its cleanup (mission memory current), so immortal and mission memory are at their
        // peak; a private memory's is its largest release.
        HvmData.put(MemoryArea.getMemoryArea(r).memoryConsumed());
        HvmData.put(Memory.getCurrentMemoryArea().consumedMemory());
        for (int a = MissionSizes.PREDICT; a < MissionSizes.AREA_COUNT; a++) {
            HvmData.put(largestRelease[a]);
        }
        HvmData.put(MissionRunFile.RELEASE_SECTION);
        for (int a = MissionSizes.PREDICT; a < MissionSizes.AREA_COUNT; a++) {
            HvmData.put(releases[a]);
            HvmData.put(allocatingReleases[a]);
            HvmData.put(allocatedBytes[a]);
        }
        written = true;
    }

    private static void putLongs(long[] a, int n) {
        for (int i = 0; i < n; i++) {
            HvmData.put(a[i]);
        }
    }

    private static void putReals(double[] a, int n) {
        for (int i = 0; i < n; i++) {
            HvmData.putReal(a[i]);
        }
    }

    /** Whether the mission handed over its records. */
    boolean written() {
        return written;
    }
}
