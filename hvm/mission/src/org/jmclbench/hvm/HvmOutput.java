package org.jmclbench.hvm;

import javax.realtime.MemoryArea;

import org.jmclbench.core.record.JobRecords;
import org.jmclbench.scj.MissionOutput;
import org.jmclbench.scj.MissionRunFile;
import org.jmclbench.scj.MissionSizes;

import vm.Memory;

/** The mission's output on the HVM: the job records, written to the result file by the natives. */
final class HvmOutput implements MissionOutput {
    private boolean written;

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
        // peak; a private memory is emptied after each release, and icecap keeps no peak of it.
        HvmData.put(MemoryArea.getMemoryArea(r).memoryConsumed());
        HvmData.put(Memory.getCurrentMemoryArea().consumedMemory());
        for (int a = MissionSizes.PREDICT; a < MissionSizes.AREA_COUNT; a++) {
            HvmData.put(-1);
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
