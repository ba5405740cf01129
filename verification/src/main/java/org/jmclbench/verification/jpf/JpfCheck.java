package org.jmclbench.verification.jpf;

import java.util.List;
import java.util.Map;

/**
 * One model check: a program (a main class run inside JPF) with its arguments, the JPF
 * configuration that states the property, and what must come out.
 *
 * @param id        unique, short, used for log file names ("P1-terminate")
 * @param property  the property in words ("P1 no deadlock")
 * @param policy    the release policy the program runs under ("skip", "terminate", "queue", or "-")
 * @param mainClass the program JPF runs
 * @param args      its arguments
 * @param config    JPF settings ({@code key=value}, passed as {@code +key=value}); listeners included
 * @param expect    holds, or the exact violation a seeded bug must produce
 * @param scope     what the inputs cover, e.g. "3 events, 4 particles, poll 2"
 */
public record JpfCheck(String id, String property, String policy, String mainClass, List<String> args,
                       Map<String, String> config, Expectation expect, String scope) {

    /** What a check's run must report. */
    public record Expectation(boolean mustHold, String propertyClass, String messageFragment) {

        /** No property violated, and the search finished without hitting a limit. */
        public static Expectation holds() {
            return new Expectation(true, null, null);
        }

        /**
         * Exactly one violation, of the JPF property (or listener) whose simple class name is
         * {@code propertyClass}, with {@code messageFragment} in its message.
         */
        public static Expectation violation(String propertyClass, String messageFragment) {
            return new Expectation(false, propertyClass, messageFragment);
        }

        /** How the verdict reads for a run that met this expectation. */
        public String describe() {
            return mustHold ? "holds" : "reports " + propertyClass + " \"" + messageFragment + "\"";
        }
    }

    /** True when this check runs a seeded bug (it must be caught). */
    public boolean seeded() {
        return !expect.mustHold();
    }
}
