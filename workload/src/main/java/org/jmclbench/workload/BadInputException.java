package org.jmclbench.workload;

/**
 * Bad usage or bad input: the message is the one line shown to the user, which names the
 * file and line or the option; the process exits with code 2 and records nothing as valid.
 */
public final class BadInputException extends Exception {
    private static final long serialVersionUID = 1L;

    public BadInputException(String message) {
        super(oneLine(message));
    }

    /**
     * The message as one line: every control character (a newline in an argument or a path)
     * as {@code \xHH}, as the C baseline's messages (native/src/options.c jm_one_line).
     */
    static String oneLine(String s) {
        StringBuilder b = null;
        for (int i = 0; i < s.length(); i++) {
            char c = s.charAt(i);
            if (c < 0x20 || c == 0x7f) {
                if (b == null) {
                    b = new StringBuilder(s.substring(0, i));
                }
                b.append("\\x").append(Character.forDigit(c >> 4, 16)).append(Character.forDigit(c & 15, 16));
            } else if (b != null) {
                b.append(c);
            }
        }
        return b == null ? s : b.toString();
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
