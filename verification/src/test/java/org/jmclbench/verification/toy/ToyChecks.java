package org.jmclbench.verification.toy;

import org.jmclbench.verification.Property;
import org.jmclbench.verification.jpf.JmmRaceDetector;
import org.jmclbench.verification.jpf.JpfCheck;
import org.jmclbench.verification.jpf.JpfCheck.Expectation;
import org.jmclbench.verification.jpf.ReleaseAllocationListener;

import java.util.ArrayList;
import java.util.EnumSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;

/**
 * The JPF checks of {@link ToyMission}: one search per policy with every property's listener
 * (the searches of one policy were identical, property by property), and each seeded bug with
 * the property it violates and where.
 */
public final class ToyChecks {
    static final int EVENTS = 3;
    static final int PARTICLES = 5;
    static final int POLL = 2;
    private static final String MAIN = ToyMission.class.getName();
    private static final String SCOPE = EVENTS + " events, " + PARTICLES + " particles, poll " + POLL;
    /**
     * What a toy search checks: the program asserts P3 (terminate), P4 and P5; JPF and listeners the
     * rest of the SCJ properties (P8 and P9 are the rtsj engine's: the toy has no lock or ATC of RTSJ).
     */
    private static final Set<Property> ALL = EnumSet.range(Property.P1, Property.P7);

    private ToyChecks() {}

    private static List<String> args(String policy, ToyFault fault) {
        return List.of(policy, Integer.toString(EVENTS), Integer.toString(PARTICLES), Integer.toString(POLL),
                fault.name());
    }

    /** Every listener: P2's race detector and P6's allocation rule (P1 is JPF's default property). */
    private static Map<String, String> config() {
        Map<String, String> c = new LinkedHashMap<>();
        c.put("listener", JmmRaceDetector.class.getName() + "," + ReleaseAllocationListener.class.getName());
        c.put("race.include", ToyMission.class.getPackageName() + ".*");
        c.put("jmclbench.release.classes", ToyMission.class.getPackageName() + ".");
        return c;
    }

    private static JpfCheck seeded(Property property, String policy, ToyFault fault, Class<?> at, String method) {
        return new JpfCheck("toy-seeded-" + fault.name().toLowerCase().replace('_', '-'), EnumSet.of(property), policy,
                MAIN, args(policy, fault), config(), Expectation.violation(property, at, method),
                SCOPE + ", seeded " + fault);
    }

    /** One search per policy, then one seeded bug per property. */
    public static List<JpfCheck> all() {
        List<JpfCheck> l = new ArrayList<>();
        for (String policy : List.of("skip", "terminate", "queue")) {
            l.add(new JpfCheck("toy-" + policy, ALL, policy, MAIN, args(policy, ToyFault.NONE), config(),
                    Expectation.holds(), SCOPE));
        }
        l.add(seeded(Property.P1, "terminate", ToyFault.LOCK_INVERSION, ToyMission.class, "release"));
        l.add(seeded(Property.P2, "terminate", ToyFault.UNGUARDED_READ, ToyRobot.class, "estimateUnguarded"));
        l.add(seeded(Property.P3, "terminate", ToyFault.COMMIT_BEFORE_POLL, ToyHandler.class, "handleAsyncEvent"));
        l.add(seeded(Property.P4, "terminate", ToyFault.WIDE_POLL, ToyHandler.class, "handleAsyncEvent"));
        l.add(seeded(Property.P5, "queue", ToyFault.LOST_RELEASE, ToyMission.class, "release"));
        l.add(seeded(Property.P6, "queue", ToyFault.STRAY_ALLOCATION, ToyHandler.class, "handleAsyncEvent"));
        return l;
    }
}
