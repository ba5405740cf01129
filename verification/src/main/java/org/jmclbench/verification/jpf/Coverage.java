package org.jmclbench.verification.jpf;

/**
 * The program's report of an outcome it reached on the current search path ("predict
 * terminated"): a no-op when run, seen by the {@link VerdictListener}, which collects the
 * outcomes of every path. A check whose search never reached an outcome it needs has passed
 * vacuously and fails (a terminate search in which no job was ever aborted proves nothing
 * about aborted jobs).
 */
public final class Coverage {
    /** The method the listener watches. */
    static final String METHOD = "reached";

    private Coverage() {}

    /** Says that this path reached {@code outcome} (a string constant: no allocation). */
    public static void reached(String outcome) {
        // Seen by the listener on entry; nothing to do in the program.
    }
}
