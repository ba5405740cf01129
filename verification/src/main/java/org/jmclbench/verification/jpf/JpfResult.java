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
 */
public record JpfResult(JpfCheck check, boolean passed, String verdict, List<String> errors,
                        long newStates, long endStates, long maxDepth, long instructions,
                        double seconds, String log) {
}
