package org.jmclbench.workload.scj;

import org.jmclbench.core.record.JobRecords;
import org.jmclbench.scj.MissionOutput;

/** The mission's output on Java SE: keeps the records so that the run writer writes them after the launcher returns. */
public final class RecordCapture implements MissionOutput {
    private JobRecords records;

    @Override
    public void missionEnded(JobRecords r) {
        this.records = r;
    }

    @Override
    public void releaseEnding(int area) {
        // rtsj-compat measures every area itself (AreaUsage)
    }

    /** The records the mission handed over, or null when it never ended. */
    public JobRecords records() {
        return records;
    }
}
