package org.jmclbench.workload.engine;

import java.util.List;

import org.jmclbench.core.record.JobRecords;
import org.jmclbench.workload.output.MemoryArea;

/** What an engine returns: every event's job record, its memory areas and its facts for summary.json. */
public final class EngineResult {
    public final JobRecords records;
    public final List<MemoryArea> areas;
    public final EngineFacts facts;

    public EngineResult(JobRecords records, List<MemoryArea> areas, EngineFacts facts) {
        this.records = records;
        this.areas = areas;
        this.facts = facts;
    }
}
