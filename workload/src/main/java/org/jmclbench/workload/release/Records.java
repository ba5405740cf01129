package org.jmclbench.workload.release;

import org.jmclbench.core.timeline.Timeline;
import org.jmclbench.core.record.JobRecords;

/** How the engine creates the records of a replay of its own (accuracy runs). */
final class Records {
    private Records() {
    }

    /** Records for a timeline of {@code events} predict events, one every {@code periodS}. */
    static JobRecords periodic(int events, double periodS) {
        double[] odo = new double[events];
        for (int k = 0; k < events; k++) {
            odo[k] = k * periodS;
        }
        return new JobRecords(Timeline.merge(odo, new double[0]), false);
    }
}
