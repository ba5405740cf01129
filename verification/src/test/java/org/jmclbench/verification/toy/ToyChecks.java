package org.jmclbench.verification.toy;

import org.jmclbench.verification.jpf.JpfCheck;
import org.jmclbench.verification.jpf.JpfCheck.Expectation;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * The JPF checks of {@link ToyMission}: each property under each policy where it applies, and
 * each seeded bug with the exact violation it must produce.
 */
public final class ToyChecks {
    static final int EVENTS = 3;
    static final int PARTICLES = 5;
    static final int POLL = 2;
    private static final String MAIN = ToyMission.class.getName();
    private static final String SCOPE = EVENTS + " events, " + PARTICLES + " particles, poll " + POLL;

    private ToyChecks() {}

    /** A property's check of the correct toy program under one policy. */
    public static JpfCheck holds(String id, String property, String policy) {
        return new JpfCheck("toy-" + id + "-" + policy, property, policy, MAIN, args(policy, ToyFault.NONE),
                config(id), Expectation.holds(), SCOPE);
    }

    /** A seeded bug's check: the property's configuration, the fault, the violation it must give. */
    public static JpfCheck seeded(String id, String property, String policy, ToyFault fault, Expectation expect) {
        return new JpfCheck("toy-" + id + "-seeded-" + fault.name().toLowerCase(), property, policy, MAIN,
                args(policy, fault), config(id), expect, SCOPE + ", seeded " + fault);
    }

    private static List<String> args(String policy, ToyFault fault) {
        return List.of(policy, Integer.toString(EVENTS), Integer.toString(PARTICLES), Integer.toString(POLL),
                fault.name());
    }

    private static Map<String, String> config(String id) {
        Map<String, String> c = new LinkedHashMap<>();
        switch (id) {
            case "P2" -> {
                c.put("listener", "gov.nasa.jpf.listener.PreciseRaceDetector");
                c.put("race.include", "org.jmclbench.verification.toy.*");
            }
            case "P6" -> {
                c.put("listener", "org.jmclbench.verification.jpf.ReleaseAllocationListener");
                c.put("jmclbench.release.classes", "org.jmclbench.verification.toy.");
            }
            default -> { }
        }
        return c;
    }

    /** Every toy check: properties under each policy, then one seeded bug per property. */
    public static List<JpfCheck> all() {
        List<JpfCheck> l = new ArrayList<>();
        for (String policy : List.of("skip", "terminate", "queue")) {
            l.add(holds("P1", "P1 no deadlock", policy));
            l.add(holds("P2", "P2 no data race", policy));
            l.add(holds("P5", "P5 every event ends exactly once", policy));
            l.add(holds("P6", "P6 no allocation in a release", policy));
        }
        l.add(holds("P3", "P3 an aborted job leaves the robot bit-identical", "terminate"));
        l.add(holds("P4", "P4 abort honoured within the poll interval", "terminate"));
        l.add(seeded("P1", "P1 no deadlock", "terminate", ToyFault.LOCK_INVERSION,
                Expectation.violation("NotDeadlockedProperty", "deadlock")));
        l.add(seeded("P2", "P2 no data race", "terminate", ToyFault.UNGUARDED_READ,
                Expectation.violation("PreciseRaceDetector", "ToyRobot@")));
        l.add(seeded("P3", "P3 an aborted job leaves the robot bit-identical", "terminate",
                ToyFault.COMMIT_BEFORE_POLL,
                Expectation.violation("NoUncaughtExceptionsProperty", "P3 an aborted job changed the robot")));
        l.add(seeded("P4", "P4 abort honoured within the poll interval", "terminate", ToyFault.WIDE_POLL,
                Expectation.violation("NoUncaughtExceptionsProperty", "P4 abort honoured later than the poll interval")));
        l.add(seeded("P5", "P5 every event ends exactly once", "queue", ToyFault.LOST_RELEASE,
                Expectation.violation("NoUncaughtExceptionsProperty", "P5 an event never ended")));
        l.add(seeded("P6", "P6 no allocation in a release", "queue", ToyFault.STRAY_ALLOCATION,
                Expectation.violation("ReleaseAllocationListener", "allocated a [D at")));
        return l;
    }
}
