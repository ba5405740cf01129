package org.jmclbench.verification.rtsj;

import org.jmclbench.verification.Property;
import org.jmclbench.verification.jpf.AtcListener;
import org.jmclbench.verification.jpf.AtomicRuntimeSyncPolicy;
import org.jmclbench.verification.jpf.HeldLockListener;
import org.jmclbench.verification.jpf.IgnoreClockReadings;
import org.jmclbench.verification.jpf.JpfCheck;
import org.jmclbench.verification.jpf.JpfCheck.Expectation;
import org.jmclbench.verification.jpf.TimedDeadlockListener;
import org.jmclbench.verification.jpf.VolatileAccessScheduler;
import org.jmclbench.verification.mission.HorizonTimeSource;

import java.util.ArrayList;
import java.util.EnumSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;

/**
 * JPF checks of the rtsj engine ({@link RtsjDriver}: the engine's replay, woven, on rtsj-compat's
 * RTSJ layer in virtual time) under terminate in both designs, and under queue (the policy where
 * two jobs contend for the robot's locks) in the thesis design only, the one that takes both of
 * those locks. The input, one particle, each job taking 5 ms of virtual time ({@link RtsjDriver}
 * has the times): under terminate, thesis: two odometry events and one laser event (the first
 * predict is fired at, the second superseded by the laser event of its instant before it starts);
 * atomic: one odometry and two laser events (the first laser release interrupts the predict, the
 * second fires at the first update while it waits for the robot); under queue one odometry and
 * one laser event at one instant (two jobs contend for the robot's locks).
 *
 * <p>One search per design and policy checks {@link #SEARCH}. The reduction is the mission
 * checks': JPF switches threads at the engine's monitors, its volatiles (the policy rule's
 * {@code latest} and {@code reserved}, the dispatcher's {@code running}, the tasks' FIFO indices), the robot's ReentrantLock and
 * every point where a thread blocks or ends, not inside rtsj-compat (the RTSJ VM's part), nor at
 * plain field accesses.
 */
public final class RtsjChecks {
    /** What one search checks. */
    public static final Set<Property> SEARCH = EnumSet.of(Property.P1, Property.P3, Property.P5, Property.P7,
            Property.P8, Property.P9);
    static final List<String> DESIGNS = List.of("thesis", "atomic");

    private RtsjChecks() {
    }

    /** The input of the searches: policy and design, odometry and laser events, one particle, a poll every 64. */
    public static List<String> args(String policy, String design, Class<?> fault) {
        List<String> a = new ArrayList<>(List.of(policy, design, String.valueOf(odometryEvents(policy, design)),
                String.valueOf(laserEvents(policy, design)), "1", "64"));
        if (fault != null) {
            a.add(fault.getName());
        }
        return a;
    }

    /** The JPF settings: the reduction and the engine's listeners (P1, P8, P9). */
    public static Map<String, String> config() {
        Map<String, String> c = new LinkedHashMap<>();
        c.put("listener", String.join(",", VolatileAccessScheduler.class.getName(),
                TimedDeadlockListener.class.getName(), HeldLockListener.class.getName(), AtcListener.class.getName()));
        c.put("vm.scheduler.sync.class", AtomicRuntimeSyncPolicy.class.getName());
        c.put("filter.instance_ammendments", IgnoreClockReadings.class.getName());
        // The replay joins its dispatcher with a hang budget: it times out only when nothing else can run.
        c.put("jmclbench.timeout.last", "true");
        c.put("jmclbench.atomic.packages", "org.jmclbench.rtsjcompat.,javax.realtime.," + HorizonTimeSource.class.getName());
        c.put("jmclbench.volatile.classes", "org.jmclbench.workload.,org.jmclbench.core.,org.jmclbench.verification.seeded.");
        c.put("vm.shared.break_on_exposure", "false");
        c.put("vm.shared.never_break_methods", "org.jmclbench.*.*");
        // The lock's own fields are not switch points: lock() and unlock() still hand over where
        // they block or wake a thread, as a monitor's enter and exit do.
        c.put("vm.shared.never_break_types", "java.util.concurrent.TimeUnit,java.util.concurrent.locks.*,"
                + "org.jmclbench.*,javax.*");
        return c;
    }

    /** What a policy's search must reach on some path (else it passed vacuously). */
    static Set<String> coverage(String policy, String design) {
        return switch (policy) {
            // thesis: the first predict is fired at (deferred), the second superseded before it starts;
            // atomic: the laser release interrupts the first predict
            case "terminate" -> design.equals("atomic") ? Set.of("predict terminated", "predict interrupted")
                    : Set.of("predict terminated", "predict deferred");
            default -> Set.of();
        };
    }

    /** terminate: a predict job fired at, and a later one in the same handler; queue: two jobs contending. */
    private static int odometryEvents(String policy, String design) {
        return policy.equals("queue") || design.equals("atomic") ? 1 : 2;
    }

    private static int laserEvents(String policy, String design) {
        return policy.equals("terminate") && design.equals("atomic") ? 2 : 1;
    }

    /** A check of the engine with a seeded fault (null: the shipped engine). */
    public static JpfCheck check(String id, Set<Property> properties, String policy, String design,
                                 Map<String, String> config, Expectation expect, Class<?> fault, String what) {
        return new JpfCheck(id, properties, policy, RtsjDriver.class.getName(), args(policy, design, fault), config,
                expect, design + " design, " + odometryEvents(policy, design) + " odometry + "
                        + laserEvents(policy, design) + " laser events (RtsjDriver's times), 1 particle"
                        + (what == null ? "" : ", " + what));
    }

    /** Per design, the shipped engine under terminate and queue. */
    public static List<JpfCheck> all() {
        List<JpfCheck> l = new ArrayList<>();
        for (String design : DESIGNS) {
            // queue (two jobs contending for the robot) in the design that takes both of its locks
            for (String policy : design.equals("thesis") ? List.of("terminate", "queue") : List.of("terminate")) {
                JpfCheck c = check("rtsj-" + design + "-" + policy, SEARCH, policy, design, config(),
                        Expectation.holdsReaching(coverage(policy, design)), null, null);
                // atomic terminate: three jobs of 5 ms virtual time contend for the robot's lock (the laser
                // release must fire at an update waiting for it); the search holds in about 190,000 states,
                // 294 s on the shared 2-core VM, past the 120 s every other check finishes in
                l.add(design.equals("atomic") && policy.equals("terminate") ? c.withBudgetFactor(5) : c);
            }
        }
        return l;
    }
}
