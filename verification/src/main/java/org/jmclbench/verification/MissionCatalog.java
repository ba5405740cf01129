package org.jmclbench.verification;

import org.jmclbench.verification.jpf.JpfCheck;

import java.util.List;
import java.util.Set;

/**
 * The checks of the real SCJ mission (scj-mission and core-immortal, on rtsj-compat): the
 * static rules on their bytecode, and the JPF checks that fit the budget (see
 * {@link MissionChecks}).
 */
public final class MissionCatalog implements CheckCatalog {
    /** The mission's release classes: what runs in a handler's release. */
    static final Set<String> RELEASES = Set.of("org/jmclbench/scj/PredictHandler", "org/jmclbench/scj/UpdateHandler",
            "org/jmclbench/scj/LaserSensor");

    @Override
    public String name() {
        return "mission";
    }

    @Override
    public List<StaticCheck> staticChecks() {
        return List.of(
                // The preallocated style: the scoped localizer is the other style's code, left out.
                new StaticCheck("P6-static-preallocated", Property.P6,
                        StaticCheck.Kind.ALLOCATION,
                        n -> isMission(n) && !n.startsWith("org/jmclbench/core/mcl/ScopedLocalizer"),
                        RELEASES::contains, MissionCatalog::isScjLayer, Set.of()),
                new StaticCheck("P4-static-abort-poll", Property.P4,
                        StaticCheck.Kind.ABORT_POLL, MissionCatalog::isMission, n -> false, n -> false, Set.of()),
                new StaticCheck("P2-static-guarded", Property.P2,
                        StaticCheck.Kind.GUARDED, MissionCatalog::isMission, n -> false, n -> false, Set.of()));
    }

    static boolean isMission(String internalName) {
        return internalName.startsWith("org/jmclbench/scj/") || internalName.startsWith("org/jmclbench/core/");
    }

    /** rtsj-compat: the SCJ API and its implementation, what an SCJ VM provides. */
    static boolean isScjLayer(String internalName) {
        return internalName.startsWith("javax/") || internalName.startsWith("org/jmclbench/rtsjcompat/");
    }

    @Override
    public List<JpfCheck> jpfChecks() {
        return MissionChecks.all();
    }
}
