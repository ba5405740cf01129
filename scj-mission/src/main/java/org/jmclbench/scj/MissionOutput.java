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

    /**
     * A release of the handler whose private memory is {@code area} ({@link MissionSizes}) is
     * ending, that memory still current and holding all the release allocated. An SCJ VM that
     * keeps no peak of a private memory (icecap empties it after each release) measures it here;
     * rtsj-compat measures its areas itself, and the JVM's output ignores the call. It must not
     * allocate or block: it runs in every release.
     */
    void releaseEnding(int area);
}
