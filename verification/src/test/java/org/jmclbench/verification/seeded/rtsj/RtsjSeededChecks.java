package org.jmclbench.verification.seeded.rtsj;

import org.jmclbench.verification.Property;
import org.jmclbench.verification.jpf.JpfCheck;
import org.jmclbench.verification.jpf.JpfCheck.Expectation;
import org.jmclbench.verification.jpf.JpfRunner;
import org.jmclbench.verification.rtsj.RtsjChecks;
import org.jmclbench.verification.seeded.mission.CommitBeforePoll;

import java.net.URISyntaxException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.EnumSet;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;

/**
 * The rtsj engine's seeded bugs, one or more per property its searches check: edits of the
 * engine's or the RTSJ layer's shipped classes ({@link EngineMutant}), and a faulty localizer
 * through the job seam. Each must be reported as its property at the edited method.
 */
public final class RtsjSeededChecks {
    private RtsjSeededChecks() {
    }

    /** The checks; the edited classes are written under {@link #mutantsRoot}. */
    public static List<JpfCheck> all() {
        Path root = mutantsRoot();
        String task = EngineMutant.TASK.replace('/', '.');
        String replay = EngineMutant.REPLAY.replace('/', '.');
        String aie = EngineMutant.AIE.replace('/', '.');
        List<JpfCheck> l = new ArrayList<>();
        l.add(mutant(root, EngineMutant.UNLOCK_NOT_IN_FINALLY, Property.P8, "terminate", "atomic",
                task + ".lockAndRun", "robot's lock released outside finally"));
        l.add(mutant(root, EngineMutant.CLEAR_FORGOTTEN, Property.P9, "terminate", "thesis",
                aie + ".doInterruptible", "doInterruptible that does not clear its AIE"));
        l.add(mutant(root, EngineMutant.AIE_ESCAPES, Property.P9, "terminate", "atomic",
                aie + ".doInterruptible", "doInterruptible that lets its AIE escape"));
        l.add(mutant(root, EngineMutant.POLL_IN_MONITOR, Property.P9, "terminate", "thesis",
                task + ".lockAndRun", "delivery points inside the robot's monitor"));
        l.add(mutant(root, EngineMutant.POLL_IN_NON_AI, Property.P9, "terminate", "atomic",
                task + ".runJob", "delivery point woven into a method that is not AI-enabled"));
        l.add(mutant(root, EngineMutant.LOST_NOTIFY, Property.P1, "queue", "thesis",
                replay + ".awaitEveryEvent", "end of an event not notified"));
        l.add(mutant(root, EngineMutant.ENDS_TWICE, Property.P5, "queue", "thesis",
                replay + ".ended", "release that ends its event twice"));
        l.add(mutant(root, EngineMutant.LATEST_LOST, Property.P7, "terminate", "thesis",
                replay + ".dispatch", "terminate rule that never records the latest release"));
        l.add(RtsjChecks.check("rtsj-seeded-commit-before-poll", EnumSet.of(Property.P3), "terminate", "atomic",
                RtsjChecks.config(), Expectation.violation(Property.P3, CommitBeforePoll.class, "predict"),
                CommitBeforePoll.class, "seeded job that applies its step before it polls"));
        return l;
    }

    /** The check of mutant {@code m}, named after it ({@code rtsj-seeded-} and its name in lower case, dashed). */
    private static JpfCheck mutant(Path root, EngineMutant m, Property p, String policy, String design, String location,
                                   String what) {
        String id = "rtsj-seeded-" + m.name().toLowerCase(Locale.ROOT).replace('_', '-');
        Map<String, String> config = RtsjChecks.config();
        config.put(JpfRunner.PREPEND, m.writeUnder(root, id).toAbsolutePath().toString());
        return RtsjChecks.check(id, EnumSet.of(p), policy, design, config, new Expectation(p, location, Set.of()), null,
                "seeded " + what + " (" + m.className() + " edited)");
    }

    /** The folder the edited classes are written under: the test classes' sibling {@code seeded-mutants}. */
    public static Path mutantsRoot() {
        return testClasses().resolveSibling("seeded-mutants");
    }

    private static Path testClasses() {
        try {
            return Path.of(RtsjSeededChecks.class.getProtectionDomain().getCodeSource().getLocation().toURI());
        } catch (URISyntaxException e) {
            throw new IllegalStateException(e);
        }
    }
}
