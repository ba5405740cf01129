package org.jmclbench.verification;

import org.jmclbench.verification.jpf.JpfCheck;
import org.jmclbench.verification.jpf.JpfHome;
import org.jmclbench.verification.jpf.JpfResult;
import org.jmclbench.verification.jpf.JpfRunner;
import org.junit.jupiter.api.Test;

import java.nio.file.Paths;

import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The mission searches check the shipped mission's own locking of the robot (the checked robot
 * adds none): with the robot's monitor taken neither by the job runner nor by
 * {@code Robot.predict} (edits of the shipped classes), the terminate search reports two jobs in
 * the localizer at once (P2), at the robot's predict.
 */
class RobotMonitorJpfTest {

    @Test
    void aPredictWithoutTheRobotsMonitorIsARace() throws Exception {
        JpfRunner runner = new JpfRunner(JpfHome.locate(), JpfRunner.currentClassPath(),
                Paths.get("target", "jpf-logs"), 120, 1024);
        JpfCheck c = SeededCatalog.predictUnlocked(MissionRun.of("terminate", "preallocated"));
        JpfResult r = runner.run(c);
        assertTrue(r.passed(), c.id() + ": " + r.verdict() + " (log " + r.log() + ")");
    }
}
