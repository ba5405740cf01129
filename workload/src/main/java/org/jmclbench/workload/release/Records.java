package org.jmclbench.workload.release;

import org.jmclbench.workload.record.JobRecords;

/** How the engine creates the records of a replay of its own (warm-up, accuracy runs). */
final class Records {
    private Records() {
    }

    static JobRecords create(int events) {
        return new JobRecords(events, false);
    }
}
