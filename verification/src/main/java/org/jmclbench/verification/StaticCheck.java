package org.jmclbench.verification;

import org.jmclbench.core.mcl.MotionModel;
import org.jmclbench.verification.bytecode.AbortPollCheck;
import org.jmclbench.verification.bytecode.AllocationCheck;
import org.jmclbench.verification.bytecode.ClassPool;
import org.jmclbench.verification.bytecode.GuardedFieldCheck;
import org.jmclbench.verification.bytecode.Violation;

import java.util.List;
import java.util.Set;
import java.util.TreeSet;
import java.util.function.Predicate;

/**
 * One static check of verify's catalogue: which classes, which rule, and either "no violation"
 * or the exact set of {@code class:method} a seeded bug must be reported at.
 *
 * @param id        short unique name
 * @param property  the property the rule is part of
 * @param kind      the rule: ALLOCATION (from releases of classes {@code releases} accepts), ABORT_POLL or GUARDED
 * @param classes   which classes of the pool the check looks at (internal names)
 * @param releases  release classes (ALLOCATION only)
 * @param layer     classes of the SCJ layer the job calls into (ALLOCATION only; looked at from the calls)
 * @param expected  empty: must hold; else the {@code class:method} of every expected violation
 */
public record StaticCheck(String id, Property property, Kind kind, Predicate<String> classes,
                          Predicate<String> releases, Predicate<String> layer, Set<String> expected) {

    /** The three static rules. */
    public enum Kind {
        ALLOCATION("no allocation reachable from a release"),
        ABORT_POLL("every particle loop polls the abort request within the poll interval"),
        GUARDED("a field guarded by its object's monitor is accessed only under it");

        /** The rule in words. */
        public final String rule;

        Kind(String rule) {
            this.rule = rule;
        }
    }

    /** The property and the rule, for the table. */
    public String propertyText() {
        return property.name() + " " + kind.rule;
    }

    /** The violations the rule finds in the pool. */
    public List<Violation> run(ClassPool pool) {
        return switch (kind) {
            case ALLOCATION -> new AllocationCheck(pool, classes, layer).check(n -> classes.test(n) && releases.test(n));
            case ABORT_POLL -> new AbortPollCheck(pool, classes, MotionModel.ABORT_BLOCK).check();
            case GUARDED -> new GuardedFieldCheck(pool, classes).check();
        };
    }

    /** True when the findings are what the check expects (none, or exactly the seeded ones). */
    public boolean met(List<Violation> found) {
        Set<String> at = new TreeSet<>();
        for (Violation v : found) {
            at.add(v.className() + ":" + v.method());
        }
        return expected.isEmpty() ? found.isEmpty() : at.equals(new TreeSet<>(expected));
    }
}
