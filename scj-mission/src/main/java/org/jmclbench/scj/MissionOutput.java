package org.jmclbench.scj;

import org.jmclbench.core.record.JobRecords;

/**
 * Where the mission's results go: called once, from the mission's cleanup after every handler
 * has ended, with the job records (in immortal memory, indexed by the merged event as
 * {@link JobRecords#timeline} orders them). On Java SE the workload keeps the reference and
 * writes the run folder after the launcher returns; an SCJ VM writes them with its own natives.
 */
public interface MissionOutput {
    /** The mission has ended: every job's times, outcome and committed estimate are in records. */
    void missionEnded(JobRecords records);
}
