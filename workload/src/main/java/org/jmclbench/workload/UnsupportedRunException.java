package org.jmclbench.workload;

/**
 * A configuration the runtime under test cannot run, though the options are well formed: a limit
 * of that runtime (the icecap HVM's 16-bit array lengths), not bad input and not a failure. The
 * message is the one line shown, naming the option; the process exits with code 3 before
 * anything is written or started, and a runner records the run as unsupported.
 */
public final class UnsupportedRunException extends Exception {
    private static final long serialVersionUID = 1L;

    public UnsupportedRunException(String message) {
        super(BadInputException.oneLine(message));
    }
}
