package org.jmclbench.tooling.cli;

import org.jmclbench.workload.BadInputException;

/**
 * Unchecked form of {@link BadInputException} for the tooling's validation code (lambdas, parsers);
 * commands turn it into the checked one, which the CLI prints as one line with exit code 2.
 */
public final class BadUsageException extends RuntimeException {
    private static final long serialVersionUID = 1L;

    public BadUsageException(String message) {
        super(message);
    }

    /** The checked exception the CLI handler understands. */
    public BadInputException checked() {
        return new BadInputException(getMessage());
    }
}
