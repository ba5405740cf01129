package org.jmclbench.workload;

/**
 * A failure of the run itself (not of its input): the message is the one line shown, the
 * process exits with code 1 and leaves only the {@code .partial} folder.
 */
public final class RunFailure extends Exception {
    private static final long serialVersionUID = 1L;

    public RunFailure(String message) {
        super(message);
    }
}
