package org.jmclbench.workload.release;

import org.jmclbench.workload.record.JobRecords;

/** Builds records the way the run does, in one place so that tests follow JobRecords' API. */
final class TestRecords {
    private TestRecords() {
    }

    static JobRecords create(int events) {
        return new JobRecords(events, false);
    }
}
