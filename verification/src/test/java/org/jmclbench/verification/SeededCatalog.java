package org.jmclbench.verification;

import org.jmclbench.verification.jpf.JpfCheck;
import org.jmclbench.verification.jpf.JpfCheck.Expectation;
import org.jmclbench.verification.mission.MissionDriver;
import org.jmclbench.verification.seeded.AllocatingRelease;
import org.jmclbench.verification.seeded.PollingJob;
import org.jmclbench.verification.seeded.mission.CommitBeforePollConfiguration;
import org.jmclbench.verification.seeded.mission.LockInversionConfiguration;
import org.jmclbench.verification.seeded.mission.LostReleaseConfiguration;
import org.jmclbench.verification.seeded.mission.PollIgnoredConfiguration;
import org.jmclbench.verification.seeded.mission.PrivateIntoMissionConfiguration;
import org.jmclbench.verification.seeded.mission.StrayAllocationConfiguration;
import org.jmclbench.verification.seeded.mission.UnguardedReadConfiguration;
import org.jmclbench.verification.toy.ToyChecks;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Set;

/**
 * The seeded bugs verify must catch (test sources: never shipped with the mission): bugs
 * plugged into the real mission through its configuration seam, the small SCJ-like program's
 * checks with one seeded bug per property, and the static checks' seeded classes.
 */
public final class SeededCatalog implements CheckCatalog {

    @Override
    public String name() {
        return "seeded";
    }

    @Override
    public List<JpfCheck> jpfChecks() {
        List<JpfCheck> l = new ArrayList<>();
        String main = MissionDriver.class.getName();
        l.add(new JpfCheck("mission-seeded-stray-allocation", "P6 no release allocates", "queue",
                main, MissionChecks.args("queue", StrayAllocationConfiguration.class.getName()),
                MissionChecks.config(), Expectation.violation("ReleaseAllocationListener", "allocated a [D at"),
                MissionChecks.scope() + ", seeded stray allocation"));
        // Only the reference listener: the stray allocation would be reported first otherwise.
        l.add(new JpfCheck("mission-seeded-private-into-mission", "P6 no reference to a shorter-lived area", "queue",
                main,
                MissionChecks.args("queue", PrivateIntoMissionConfiguration.class.getName()),
                MissionChecks.configWith("org.jmclbench.verification.jpf.AreaReferenceListener"),
                Expectation.violation("AreaReferenceListener", "stores a reference to an object of [D in"),
                MissionChecks.scope() + ", seeded private-memory array kept by the mission's localizer"));
        // The inversion deadlocks when a laser release falls within a predict job.
        l.add(new JpfCheck("mission-seeded-lock-inversion", "P1 no deadlock", "queue", main,
                MissionChecks.args("queue", LockInversionConfiguration.class.getName()), MissionChecks.config(),
                Expectation.violation("NotDeadlockedProperty", "deadlock"),
                MissionChecks.scope() + ", seeded robot/gate lock-order inversion"));
        l.add(new JpfCheck("mission-seeded-lost-release", "P5 every event ends exactly once", "queue",
                main, MissionChecks.args("queue", LostReleaseConfiguration.class.getName()),
                MissionChecks.config(), Expectation.violation("NoUncaughtExceptionsProperty", "P5 an event never ended"),
                MissionChecks.scope() + ", seeded gate ending the mission after the first event"));
        // P3 and P4 run without the P6 listeners, as their violation (an AssertionError) allocates.
        Map<String, String> p3p4 = MissionChecks.configWith();
        l.add(new JpfCheck("mission-seeded-unguarded-read", MissionChecks.RACE_PROPERTY, "terminate", main,
                MissionChecks.raceArgs("terminate", UnguardedReadConfiguration.class.getName()),
                MissionChecks.raceConfig(), Expectation.violation("JmmRaceDetector", ".admitted"),
                MissionChecks.raceScope() + ", seeded admission count read by the abort poll without the gate's lock"));
        l.add(new JpfCheck("mission-seeded-commit-before-poll", "P3 an aborted job leaves the robot bit-identical",
                "terminate", main, MissionChecks.args("terminate", CommitBeforePollConfiguration.class.getName()),
                p3p4, Expectation.violation("NoUncaughtExceptionsProperty", "P3 an aborted job changed the robot"),
                MissionChecks.scope() + ", seeded job that applies its step before it polls"));
        l.add(new JpfCheck("mission-seeded-poll-ignored", "P4 abort honoured at the first poll", "terminate", main,
                MissionChecks.args("terminate", PollIgnoredConfiguration.class.getName()),
                p3p4, Expectation.violation("NoUncaughtExceptionsProperty",
                        "P4 a job went on after a poll saw its abort request"),
                MissionChecks.scope() + ", seeded job that carries on after seeing the request"));
        l.addAll(ToyChecks.all());
        return l;
    }

    @Override
    public List<StaticCheck> staticChecks() {
        String alloc = AllocatingRelease.class.getName();
        String poll = PollingJob.class.getName();
        return List.of(
                new StaticCheck("static-seeded-allocation", "P6 no allocation reachable from a release",
                        StaticCheck.Kind.ALLOCATION, n -> n.startsWith("org/jmclbench/verification/seeded/"),
                        n -> n.equals(internal(alloc)),
                        Set.of(alloc + ":handleAsyncEvent", alloc + ":helper", alloc + "$AllocatingStep:apply")),
                new StaticCheck("static-seeded-abort-poll", "P4 every particle loop polls the abort request",
                        StaticCheck.Kind.ABORT_POLL, n -> n.equals(internal(poll)), n -> false,
                        Set.of(poll + ":update", poll + ":siblings")));
    }

    private static String internal(String className) {
        return className.replace('.', '/');
    }
}
