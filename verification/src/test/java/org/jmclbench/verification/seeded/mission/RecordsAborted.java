package org.jmclbench.verification.seeded.mission;

import org.jmclbench.core.mcl.AbortSignal;
import org.jmclbench.core.mcl.Localizer;
import org.jmclbench.scj.ImmortalEntry;
import org.jmclbench.verification.mission.CheckedRobot;
import org.jmclbench.verification.mission.MissionFault;

/**
 * Seeded P3 bug in what is recorded: the robot writes the estimate into an aborted predict job's
 * record (as a commit made before the job's result is checked does). The localizer is
 * unchanged; the functional oracle sees a result recorded for an event whose job did not complete.
 */
public final class RecordsAborted implements MissionFault {

    @Override
    public CheckedRobot robot(Localizer localizer, ImmortalEntry entry) {
        return new Recording(localizer, entry);
    }

    /** Records the estimate whatever the job's outcome. */
    public static final class Recording extends CheckedRobot {
        Recording(Localizer localizer, ImmortalEntry entry) {
            super(localizer, entry);
        }

        @Override
        public synchronized boolean predict(int k, AbortSignal abort) {
            boolean done = super.predict(k, abort);
            entry.records.estX[k] = localizer.estimateX();
            return done;
        }
    }
}
