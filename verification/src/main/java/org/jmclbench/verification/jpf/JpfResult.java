package org.jmclbench.verification.jpf;

import java.util.List;

/**
 * What one JPF run reported: its errors, how much it explored, and whether it met its check's
 * expectation.
 *
 * @param check        the check that ran
 * @param passed       true when the outcome is the expected one (holds, or exactly the seeded violation)
 * @param verdict      one line: "holds", "caught: ...", or why it failed
 * @param errors       each reported violation as "PropertyClass: first line of the message"
 * @param newStates    states JPF generated
 * @param endStates    end states reached
 * @param maxDepth     deepest search path
 * @param instructions bytecode instructions executed
 * @param seconds      wall time of the forked JPF run
 * @param log          where JPF's full console output was kept
 * @param failure      why it did not pass, or null when it passed
 */
public record JpfResult(JpfCheck check, boolean passed, String verdict, List<String> errors,
                        long newStates, long endStates, long maxDepth, long instructions,
                        double seconds, String log, Failure failure) {

    /**
     * Why a check did not pass, for a reader that must tell a bug found from a run cut short (the
     * mutation score: a check over its wall-clock budget on a loaded machine has found nothing).
     */
    public enum Failure {
        /** A property was violated (or a seeded check reported other than its bug). */
        VIOLATION("violation"),
        /** A seeded bug went unreported. */
        MISSED("missed"),
        /** Every path held, but no path reached an outcome the check must cover. */
        VACUOUS("vacuous"),
        /** JPF hit a search limit (depth, heap): the state space was not covered. */
        SEARCH_LIMIT("search-limit"),
        /** JPF ended without writing a verdict (the JVM crashed, or JPF could not start). */
        NO_VERDICT("no-verdict"),
        /** Still searching when its wall-clock budget ran out: no verdict, and possibly only load. */
        OVER_BUDGET("over-budget");

        private final String key;

        Failure(String key) {
            this.key = key;
        }

        /** The name written to verification.json's {@code failure} field. */
        public String key() {
            return key;
        }
    }
}
