package org.jmclbench.tooling.cli;

/**
 * Bad usage or bad input to a tooling command: the message is the one line shown to the user,
 * naming the option, or the file and line; the command line prints it and exits with code 2,
 * and nothing is recorded as valid. Unchecked, so that parsers and lambdas can throw it.
 */
public final class BadUsageException extends RuntimeException {
    private static final long serialVersionUID = 1L;

    public BadUsageException(String message) {
        super(message);
    }

    /** A problem at a line of a file, shown as {@code file:line: problem}. */
    public static BadUsageException atLine(String file, int line, String problem) {
        return new BadUsageException(file + ":" + line + ": " + problem);
    }

    /** A problem with a command-line option, shown as {@code option: problem}. */
    public static BadUsageException ofOption(String option, String problem) {
        return new BadUsageException(option + ": " + problem);
    }
}
