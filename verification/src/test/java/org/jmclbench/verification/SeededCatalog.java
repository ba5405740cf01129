package org.jmclbench.verification;

import org.jmclbench.verification.jpf.JpfCheck;
import org.jmclbench.verification.jpf.JpfCheck.Expectation;
import org.jmclbench.verification.mission.MissionDriver;
import org.jmclbench.verification.seeded.AllocatingRelease;
import org.jmclbench.verification.seeded.PollingJob;
import org.jmclbench.verification.seeded.mission.LockInversionConfiguration;
import org.jmclbench.verification.seeded.mission.LostReleaseConfiguration;
import org.jmclbench.verification.seeded.mission.PrivateIntoMissionConfiguration;
import org.jmclbench.verification.seeded.mission.StrayAllocationConfiguration;
import org.jmclbench.verification.toy.ToyChecks;

import java.util.ArrayList;
import java.util.LinkedHashMap;
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
        l.add(new JpfCheck("mission-seeded-stray-allocation", "P6 no release allocates", "queue",
                MissionDriver.class.getName(), MissionChecks.args("queue", StrayAllocationConfiguration.class.getName()),
                MissionChecks.config(), Expectation.violation("ReleaseAllocationListener", "allocated a [D at"),
                MissionChecks.scope() + ", seeded stray allocation"));
        // Only the reference listener: the stray allocation would be reported first otherwise.
        l.add(new JpfCheck("mission-seeded-private-into-mission", "P6 no reference to a shorter-lived area", "queue",
                MissionDriver.class.getName(),
                MissionChecks.args("queue", PrivateIntoMissionConfiguration.class.getName()),
                MissionChecks.config("org.jmclbench.verification.jpf.AreaReferenceListener"),
                Expectation.violation("AreaReferenceListener", "stores a reference to an object of [D in"),
                MissionChecks.scope() + ", seeded private-memory array kept by the mission's localizer"));
        // The inversion needs a laser release while a predict job runs: one laser event at the
        // odometry event's instant. Exhausting that input is over budget, so this search is
        // steered to states with the most blocked threads (JPF's MostBlocked heuristic).
        Map<String, String> deadlock = new LinkedHashMap<>(MissionChecks.config());
        deadlock.put("search.class", "gov.nasa.jpf.search.heuristic.MostBlocked");
        l.add(new JpfCheck("mission-seeded-lock-inversion", "P1 no deadlock", "queue", MissionDriver.class.getName(),
                MissionChecks.args("queue", 1, 1, LockInversionConfiguration.class.getName()), deadlock,
                Expectation.violation("NotDeadlockedProperty", "deadlock"),
                MissionChecks.scope(1, 1) + ", most-blocked-first search, seeded robot/gate lock-order inversion"));
        l.add(new JpfCheck("mission-seeded-lost-release", "P5 every event ends exactly once", "queue",
                MissionDriver.class.getName(), MissionChecks.args("queue", LostReleaseConfiguration.class.getName()),
                MissionChecks.config(), Expectation.violation("NoUncaughtExceptionsProperty", "P5 an event never ended"),
                MissionChecks.scope() + ", seeded gate ending the mission after the first event"));
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
