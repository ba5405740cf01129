package org.jmclbench.verification.mission;

import org.jmclbench.core.record.JobRecords;
import org.jmclbench.verification.Property;

/**
 * P7 on a run's job records in virtual time, where a job takes a fixed time and "busy" is exact: skip
 * drops an event only while an admitted job holds the robot (one before it in timeline order that
 * ended at or after its release), and terminate aborts a job only when an event after it in
 * timeline order was released before its end. Timeline order, not release time: of two events at
 * one instant only the first can make the second's drop, and only the second the first's abort
 * (docs/RELEASE-ENGINE.md, "Events at the same time"). A drop or abort with no such event is the policy's decision
 * made wrongly; it is blamed on {@code culprit}'s {@code dropMethod} or {@code abortMethod}.
 */
public final class PolicyOracle {
    private PolicyOracle() {
    }

    /** Throws a located P7 failure at the first event dropped or aborted against its policy. */
    public static void check(JobRecords r, Object culprit, String dropMethod, String abortMethod) {
        PropertyFailure p7 = new PropertyFailure(Property.P7, "an event was dropped or aborted against its policy");
        for (int k = 0; k < r.size(); k++) {
            if (r.outcome[k] == JobRecords.SKIPPED) {
                boolean busy = false;
                for (int j = 0; j < r.size(); j++) {
                    busy |= j < k && r.outcome[j] != JobRecords.SKIPPED && r.releaseNs[j] <= r.releaseNs[k]
                            && r.endNs[j] >= r.releaseNs[k];
                }
                p7.unless(busy, culprit, dropMethod);
            } else if (r.outcome[k] == JobRecords.TERMINATED) {
                long end = r.startNs[k] < 0 ? Long.MAX_VALUE : r.endNs[k];
                boolean superseded = false;
                for (int j = 0; j < r.size(); j++) {
                    superseded |= j > k && r.releaseNs[j] >= r.releaseNs[k] && r.releaseNs[j] <= end;
                }
                p7.unless(superseded, culprit, abortMethod);
            }
        }
    }
}
