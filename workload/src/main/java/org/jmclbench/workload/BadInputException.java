package org.jmclbench.workload;

/**
 * Bad usage or bad input: the message is the one line shown to the user, which names the
 * file and line or the option; the process exits with code 2 and records nothing as valid.
 */
public final class BadInputException extends Exception {
    private static final long serialVersionUID = 1L;

    public BadInputException(String message) {
        super(message);
    }

    /** A problem at a line of a data file, shown as {@code file:line: problem}. */
    public static BadInputException atLine(String file, int line, String problem) {
        return new BadInputException(file + ":" + line + ": " + problem);
    }

    /** A problem with a command-line option, shown as {@code option: problem}. */
    public static BadInputException ofOption(String option, String problem) {
        return new BadInputException(option + ": " + problem);
    }
}
