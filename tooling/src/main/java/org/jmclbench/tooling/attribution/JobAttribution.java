package org.jmclbench.tooling.attribution;

import java.util.List;

/**
 * The causes of one missed or late job, largest first.
 *
 * @param windowStartNs start of the window searched for causes (ns from the run start)
 * @param windowEndNs   end of that window
 * @param blockedBy     for a skipped job, the job that held the robot ({@code task#index}), else null
 */
public record JobAttribution(String task, int index, String outcome, long windowStartNs, long windowEndNs,
        String blockedBy, List<Cause> causes) {

    /** The cause that accounts for the most time ({@code unknown} when none was found). */
    public Cause primary() {
        return causes.get(0);
    }
}
