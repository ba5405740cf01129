package org.jmclbench.verification;

import org.jmclbench.core.policy.OverrunPolicy;
import org.jmclbench.verification.jpf.AreaReferenceListener;
import org.jmclbench.verification.jpf.AtomicRuntimeSyncPolicy;
import org.jmclbench.verification.jpf.ConstructedFinalsSharednessPolicy;
import org.jmclbench.verification.jpf.JmmRaceDetector;
import org.jmclbench.verification.jpf.JpfCheck;
import org.jmclbench.verification.jpf.JpfCheck.Expectation;
import org.jmclbench.verification.jpf.ReleaseAllocationListener;
import org.jmclbench.verification.jpf.VolatileAccessScheduler;
import org.jmclbench.verification.mission.HorizonTimeSource;
import org.jmclbench.verification.mission.MissionDriver;

import java.util.ArrayList;
import java.util.EnumSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.stream.Stream;

/**
 * JPF checks of the real mission ({@link MissionDriver}: scj-mission on rtsj-compat with virtual
 * time), under skip, terminate and queue, in both memory styles. The input ({@link MissionRun#of}):
 * two odometry events 50 ms apart and two laser events, 2 ms after the first and 2 ms before the
 * second, one particle. Each job takes 5 ms of virtual time ({@link MissionDriver#JOB_COST_NS}), so
 * the first laser event falls within the first predict and the second predict within the second
 * update: on this input the terminate policy aborts a job of each task, skip drops an event of each
 * task and queue makes them wait, and the periodic, one-shot and aperiodic handlers are each
 * released twice. (Events at one instant no longer overlap: the rule decides them all before any
 * of their jobs starts, docs/RELEASE-ENGINE.md.)
 *
 * <p>One search per policy and style checks {@link #SEARCH}: P1 (JPF's deadlock property), P2 of
 * the robot (no two jobs in its localizer at once), P3 and P4 (the
 * {@link org.jmclbench.verification.mission.CheckedRobot} inside every job, and the driver's
 * functional oracle), P5 (the driver, from the gate's count and the job records, and the
 * horizon of virtual time), P6 (in the preallocated style: no allocation in a release; in both:
 * no reference to a shorter-lived area, and the private memory empty after each release) and P7
 * (the driver, from the job records: {@link org.jmclbench.verification.mission.PolicyOracle}). A
 * search per property would explore the same states once per property. A policy's search must
 * also reach the outcome it exists for (terminate: an aborted job of each task; skip: a dropped
 * event of each task), else it passed vacuously. P2 has its own search per policy, on the same two
 * odometry and two laser events, switching at every field access of the mission.
 *
 * <p>Reduction: JPF switches threads at the mission's synchronisation actions (monitors, its
 * volatile abort request, thread start and end, blocking) and not inside rtsj-compat, which
 * plays the SCJ VM ({@link AtomicRuntimeSyncPolicy}), nor at plain field accesses. For a
 * program without data races that is every behaviour of the mission; the P2 searches, which
 * also switch at every field access of the mission's classes, establish that it has none.
 */
public final class MissionChecks {
    /** What one mission search checks. */
    public static final Set<Property> SEARCH = EnumSet.of(Property.P1, Property.P2, Property.P3, Property.P4,
            Property.P5, Property.P6, Property.P7);
    /** Every policy of the one definition (core-immortal's OverrunPolicy): a new one is searched as the others are. */
    static final List<String> POLICIES = Stream.of(OverrunPolicy.values()).map(p -> p.label).toList();
    static final List<String> STYLES = List.of("preallocated", "scoped");

    /**
     * Fields whose stores the reference listener lets pass, each a known finding awaiting a fix
     * (none now: the first, MclMission's robot and gate fields, was fixed in the mission).
     */
    static final List<String> KNOWN_AREA_FINDINGS = List.of();

    /** The mission's code (with the seeded bugs plugged into it), as class-name prefixes. */
    static final String MISSION_CODE = "org.jmclbench.scj.,org.jmclbench.core.,org.jmclbench.verification.seeded.";

    /** The code whose field accesses the race detector judges. */
    static final String RACE_SCOPE = "org.jmclbench.scj.*,org.jmclbench.core.*,org.jmclbench.verification.seeded.*";

    private MissionChecks() {}

    /**
     * The JPF settings of a mission search in a memory style: the reduction, and P6's listeners
     * (a scoped release allocates in its private memory by design, so only the reference and
     * emptiness rules apply there).
     */
    public static Map<String, String> config(String memory) {
        Map<String, String> c = memory.equals("scoped") ? scheduling(AreaReferenceListener.class)
                : scheduling(ReleaseAllocationListener.class, AreaReferenceListener.class);
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
     * robot's synchronized predict and update, and the mission searches check that no two jobs
     * are in it at once (the checked robot's P2).
     */
    public static Map<String, String> raceConfig() {
        Map<String, String> c = scheduling(JmmRaceDetector.class);
        c.put("race.include", RACE_SCOPE);
        c.put("vm.shared.always_break_types", "org.jmclbench.scj.*,org.jmclbench.verification.seeded.*");
        c.put("vm.shared.never_break_types", "java.*,jdk.*,javax.*,org.jmclbench.rtsjcompat.*");
        c.put("vm.scheduler.sharedness.class", ConstructedFinalsSharednessPolicy.class.getName());
        return c;
    }

    /** Switch at the mission's monitors and volatiles, not inside the SCJ layer. */
    private static Map<String, String> scheduling(Class<?>... listeners) {
        Map<String, String> c = new LinkedHashMap<>();
        List<String> all = new ArrayList<>(List.of(VolatileAccessScheduler.class.getName()));
        for (Class<?> l : listeners) {
            all.add(l.getName());
        }
        c.put("listener", String.join(",", all));
        c.put("vm.scheduler.sync.class", AtomicRuntimeSyncPolicy.class.getName());
        // The SCJ layer, and the driver's horizon on its clock, act as the VM: not preempted inside.
        c.put("jmclbench.atomic.packages", "org.jmclbench.rtsjcompat.,javax.realtime.,javax.safetycritical.,"
                + HorizonTimeSource.class.getName());
        c.put("jmclbench.volatile.classes", MISSION_CODE);
        c.put("jmclbench.release.classes", "org.jmclbench.scj.");
        c.put("jmclbench.areas.known", String.join(",", KNOWN_AREA_FINDINGS));
        c.put("vm.shared.break_on_exposure", "false");
        c.put("vm.shared.never_break_types", "java.util.concurrent.TimeUnit,org.jmclbench.*,javax.*");
        return c;
    }

    /** The outcomes a policy's search must reach on some path (else it passed vacuously). */
    public static Set<String> coverage(String policy) {
        return switch (policy) {
            case "terminate" -> Set.of("predict terminated", "update terminated");
            case "skip" -> Set.of("predict skipped", "update skipped");
            default -> Set.of();
        };
    }

    /** A mission check: {@code run} with {@code fault} (null: the shipped mission) under {@code config}. */
    public static JpfCheck check(String id, Set<Property> properties, MissionRun run, Map<String, String> config,
                                 Expectation expect, Class<?> fault, String what) {
        return new JpfCheck(id, properties, run.policy(), MissionDriver.class.getName(), run.args(fault), config,
                expect, run.scope() + (what == null ? "" : ", " + what));
    }

    /**
     * The P2 searches' input for a policy: the mission searches' own (two odometry and two laser
     * events), which fits the budget since a constructed object's final fields are no switch points
     * ({@link ConstructedFinalsSharednessPolicy}; before, one event of each took longer).
     */
    public static MissionRun raceRun(String policy) {
        return MissionRun.of(policy, "preallocated");
    }

    /**
     * The P4 interval search's input (terminate, the mission searches' events): five particles and a poll every two, so that a job polling less than once per
     * interval makes fewer polls than a complete pass needs; with the covariance computed, so
     * that the {@code -c} path runs too.
     */
    public static MissionRun intervalRun() {
        return MissionRun.of("terminate", "preallocated").particles(5, 2).withCovariance();
    }

    /** Per policy and style, the shipped mission's search; the interval search; per policy, its P2 search. */
    public static List<JpfCheck> all() {
        List<JpfCheck> l = new ArrayList<>();
        for (String memory : STYLES) {
            for (String policy : POLICIES) {
                l.add(check("mission-" + memory + "-" + policy, SEARCH, MissionRun.of(policy, memory), config(memory),
                        Expectation.holdsReaching(coverage(policy)), null, null));
            }
        }
        l.add(check("mission-interval-terminate", SEARCH, intervalRun(), config("preallocated"),
                Expectation.holdsReaching(coverage("terminate")), null, null));
        for (String policy : POLICIES) {
            l.add(check("mission-race-" + policy, EnumSet.of(Property.P2), raceRun(policy), raceConfig(),
                    Expectation.holds(), null, "switching at every field access of the mission"));
        }
        return l;
    }
}
