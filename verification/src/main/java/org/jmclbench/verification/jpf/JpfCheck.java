package org.jmclbench.verification.jpf;

import org.jmclbench.verification.Property;

import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.stream.Collectors;

/**
 * One model check: a program (a main class run inside JPF) with its arguments, the JPF
 * configuration that states the properties, and what must come out.
 *
 * @param id         unique, short, used for log file names ("mission-terminate")
 * @param properties what one search checks (splitting a search per property would repeat it)
 * @param policy     the release policy the program runs under ("skip", "terminate", "queue", or "-")
 * @param mainClass  the program JPF runs
 * @param args       its arguments
 * @param config     JPF settings ({@code key=value}, passed as {@code +key=value}); listeners included
 * @param expect     holds, or the property a seeded bug violates and where
 * @param scope      what the inputs cover, e.g. "3 events, 4 particles, poll 2"
 * @param budgetFactor how many times the run's wall-clock budget this check gets: 1, or more for a
 *                     search known to need it (its states said where it is made), never to hide a hang
 */
public record JpfCheck(String id, Set<Property> properties, String policy, String mainClass, List<String> args,
                       Map<String, String> config, Expectation expect, String scope, int budgetFactor) {

    /** A check within the run's budget. */
    public JpfCheck(String id, Set<Property> properties, String policy, String mainClass, List<String> args,
                    Map<String, String> config, Expectation expect, String scope) {
        this(id, properties, policy, mainClass, args, config, expect, scope, 1);
    }

    /** This check with {@code factor} times the run's budget. */
    public JpfCheck withBudgetFactor(int factor) {
        return new JpfCheck(id, properties, policy, mainClass, args, config, expect, scope, factor);
    }

    /**
     * What a check's run must report: nothing (and the search finished without hitting a limit,
     * having reached every outcome in {@code coverage}), or exactly one violation of
     * {@code violated} located at {@code location} ({@code Class.method}).
     *
     * @param coverage names of the outcomes a search must reach on some path, else it passed
     *                 vacuously (for example "a terminated predict job"); see {@link Coverage}
     */
    public record Expectation(Property violated, String location, Set<String> coverage) {

        /** No property violated, and the search finished without hitting a limit. */
        public static Expectation holds() {
            return new Expectation(null, null, Set.of());
        }

        /** As {@link #holds()}, and some path reaches each outcome named. */
        public static Expectation holdsReaching(Set<String> coverage) {
            return new Expectation(null, null, Set.copyOf(coverage));
        }

        /** Exactly one violation, of {@code violated}, located in {@code culprit}'s {@code method}. */
        public static Expectation violation(Property violated, Class<?> culprit, String method) {
            return new Expectation(violated, culprit.getName() + "." + method, Set.of());
        }

        /** Whether the run must find nothing. */
        public boolean mustHold() {
            return violated == null;
        }

        /** How the verdict reads for a run that met this expectation. */
        public String describe() {
            return mustHold() ? "holds" : "reports " + violated.name() + " at " + location;
        }
    }

    /** True when this check runs a seeded bug (it must be caught). */
    public boolean seeded() {
        return !expect.mustHold();
    }

    /** The properties in words: one property's label, or the names of several. */
    public String propertyText() {
        if (properties.size() == 1) {
            return properties.iterator().next().label();
        }
        return properties.stream().sorted().map(Property::name).collect(Collectors.joining(" "));
    }
}
