package org.jmclbench.verification;

import org.jmclbench.core.policy.OverrunPolicy;
import org.jmclbench.verification.jpf.AtomicRuntimeSyncPolicy;
import org.jmclbench.verification.jpf.JpfCheck;
import org.jmclbench.verification.jpf.JpfCheck.Expectation;
import org.jmclbench.verification.mission.MissionDriver;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * JPF checks of the real mission ({@link MissionDriver}: scj-mission on rtsj-compat with virtual
 * time), each under skip, terminate and queue. The input: two odometry events 50 ms apart and
 * two laser events, each at the instant of an odometry event, one particle. Virtual time stands
 * still while a job runs, so a release falls within a job only at the same instant: on this
 * input the terminate policy aborts, skip drops and queue waits, and the periodic, one-shot
 * and aperiodic handlers are each released twice.
 *
 * <p>Each search checks P1 (JPF's deadlock property), P3 and P4 (the {@link
 * org.jmclbench.verification.mission.CheckedLocalizer} around the mission's localizer), P5
 * (the driver, from the job records) and P6 (both listeners). P2 has its own search per policy,
 * on one odometry and one laser event (on two of each it took 188,900 states and 110 s).
 *
 * <p>Reduction: JPF switches threads at the mission's synchronisation actions (monitors, its
 * volatile abort request, thread start and end, blocking) and not inside rtsj-compat, which
 * plays the SCJ VM ({@link AtomicRuntimeSyncPolicy}), nor at plain field accesses. For a
 * program without data races that is every behaviour of the mission; the P2 searches, which
 * also switch at every field access of the mission's classes, establish that it has none.
 */
public final class MissionChecks {
    static final int ODOMETRY = 2;
    static final int LASER = 2;
    static final int RACE_ODOMETRY = 1;
    static final int RACE_LASER = 1;
    static final int PARTICLES = 1;
    static final String PROPERTY = "P1 no deadlock, P3 an aborted job leaves the robot bit-identical, "
            + "P4 abort honoured at the first poll, P5 each event ends once, P6 no release allocates, "
            + "no reference to a shorter-lived area";
    static final String RACE_PROPERTY = "P2 no data race on mission or robot state";
    private static final String JPF = "org.jmclbench.verification.jpf.";

    /**
     * Fields whose stores the reference listener lets pass, each a known finding awaiting a fix
     * (none now: the first, MclMission's robot and gate fields, was fixed in the mission).
     */
    static final List<String> KNOWN_AREA_FINDINGS = List.of();

    private MissionChecks() {}

    /** The JPF settings every mission check uses (the reduction, and both P6 listeners). */
    public static Map<String, String> config() {
        return configWith(JPF + "ReleaseAllocationListener", JPF + "AreaReferenceListener");
    }

    /**
     * The mission checks' settings with only the given listeners: a seeded bug checked by one, or
     * none (a P3 or P4 violation is an AssertionError, itself an allocation in the release).
     */
    public static Map<String, String> configWith(String... listeners) {
        Map<String, String> c = scheduling(listeners);
        // No thread switch at plain field and array accesses anywhere (the P2 searches' part).
        c.put("vm.shared.never_break_methods", "org.jmclbench.*.*");
        return c;
    }

    /**
     * The P2 searches' settings: JPF also switches threads at every field access of the mission's
     * classes (and the seeded bugs'), whoever holds which lock, and the race detector looks at
     * each switch for two threads about to make conflicting plain accesses to the same field.
     * The localizer's own fields and arrays are not switch points (switching there too took
     * 186,613 states and 99 s for terminate alone): the mission reaches it only inside the
     * robot's synchronized predict and update, which these searches do not re-check.
     */
    public static Map<String, String> raceConfig() {
        Map<String, String> c = scheduling(JPF + "JmmRaceDetector");
        c.put("race.include", RACE_SCOPE);
        c.put("vm.shared.always_break_types", "org.jmclbench.scj.*,org.jmclbench.verification.seeded.*");
        c.put("vm.shared.never_break_types", "java.*,jdk.*,javax.*,org.jmclbench.rtsjcompat.*");
        return c;
    }

    /** Switch at the mission's monitors and volatiles, not inside the SCJ layer. */
    private static Map<String, String> scheduling(String... listeners) {
        Map<String, String> c = new LinkedHashMap<>();
        List<String> all = new ArrayList<>(List.of(JPF + "VolatileAccessScheduler"));
        all.addAll(List.of(listeners));
        c.put("listener", String.join(",", all));
        c.put("vm.scheduler.sync.class", AtomicRuntimeSyncPolicy.class.getName());
        c.put("jmclbench.volatile.classes", MISSION_CODE);
        c.put("jmclbench.release.classes", "org.jmclbench.scj.");
        c.put("jmclbench.areas.known", String.join(",", KNOWN_AREA_FINDINGS));
        c.put("vm.shared.break_on_exposure", "false");
        c.put("vm.shared.never_break_types", "java.util.concurrent.TimeUnit,org.jmclbench.*,javax.*");
        return c;
    }

    /** The mission's code (with the seeded bugs plugged into it), as class-name prefixes. */
    static final String MISSION_CODE = "org.jmclbench.scj.,org.jmclbench.core.,org.jmclbench.verification.seeded.";

    /** The code whose field accesses the race detector judges. */
    static final String RACE_SCOPE = "org.jmclbench.scj.*,org.jmclbench.core.*,org.jmclbench.verification.seeded.*";

    /** The scope of a mission check, for the table and the JSON. */
    public static String scope() {
        return scope(ODOMETRY, LASER);
    }

    /** The scope of a check on {@code odometry} and {@code laser} events. */
    public static String scope(int odometry, int laser) {
        return odometry + " odometry + " + laser + " laser events" + (laser > 0 ? " (coinciding)" : "") + ", "
                + PARTICLES + " particle, poll every 64";
    }

    /** The driver's arguments for a policy and an optional configuration class (a seam). */
    public static List<String> args(String policy, String configurationClass) {
        return args(policy, ODOMETRY, LASER, configurationClass);
    }

    /** As {@link #args(String, String)}, on {@code odometry} and {@code laser} events. */
    public static List<String> args(String policy, int odometry, int laser, String configurationClass) {
        List<String> a = new ArrayList<>(List.of(policy, Integer.toString(odometry), Integer.toString(laser),
                Integer.toString(PARTICLES)));
        if (configurationClass != null) {
            a.add(configurationClass);
        }
        return a;
    }

    /** The driver's arguments on the P2 searches' input. */
    public static List<String> raceArgs(String policy, String configurationClass) {
        return args(policy, RACE_ODOMETRY, RACE_LASER, configurationClass);
    }

    /** The scope of a P2 search. */
    public static String raceScope() {
        return scope(RACE_ODOMETRY, RACE_LASER) + ", switching at every field access of the mission";
    }

    /** Per policy: the correct mission's search, and its P2 search. */
    public static List<JpfCheck> all() {
        List<JpfCheck> l = new ArrayList<>();
        String main = MissionDriver.class.getName();
        for (OverrunPolicy p : OverrunPolicy.values()) {
            String policy = p.label;
            l.add(new JpfCheck("mission-" + policy, PROPERTY, policy, main, args(policy, null), config(),
                    Expectation.holds(), scope()));
            l.add(new JpfCheck("mission-race-" + policy, RACE_PROPERTY, policy, main, raceArgs(policy, null),
                    raceConfig(), Expectation.holds(), raceScope()));
        }
        return l;
    }
}
