package org.jmclbench.verification;

import java.io.PrintStream;
import java.io.PrintWriter;
import java.nio.file.Path;

import picocli.CommandLine;
import picocli.CommandLine.ITypeConverter;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.TypeConversionException;

/** How verification's commands read their options: picocli, with bad usage as one line and exit 2. */
final class CommandLines {
    /** Exit code for bad usage or bad input, as every jmclbench command. */
    static final int EXIT_BAD_INPUT = 2;

    private CommandLines() {
    }

    /**
     * Fills {@code command}'s options from {@code args} ({@code name}: the launcher's command).
     * Returns null when the command should go on, else its exit code: 0 after printing the usage
     * for {@code --help}, 2 after one line on {@code err}. An option given twice takes its last
     * value (the launcher gives defaults first). An empty path is refused, as tooling's commands do.
     */
    static Integer parse(Object command, String name, String[] args, PrintStream out, PrintStream err) {
        CommandLine cli = new CommandLine(command).setCommandName("jmclbench " + name).setOverwrittenOptionsAllowed(true);
        cli.registerConverter(Path.class, CommandLines::path);
        try {
            cli.parseArgs(args);
        } catch (ParameterException e) {
            return bad(err, name, e.getMessage());
        }
        if (cli.isUsageHelpRequested()) {
            PrintWriter w = new PrintWriter(out, true);
            cli.usage(w);
            w.flush();
            return 0;
        }
        return null;
    }

    /** One line, {@code jmclbench: COMMAND: MESSAGE}, and the exit code of bad input. */
    static int bad(PrintStream err, String command, String message) {
        err.println("jmclbench: " + command + ": " + message);
        return EXIT_BAD_INPUT;
    }

    /**
     * A path option's value. An empty one is refused: Path.of("") is the working folder, so an unset
     * variable ({@code --logs "$DIR"}) put the logs there. Tooling's converter (JmclbenchCli) does the
     * same; verification does not depend on tooling, so it is repeated here.
     */
    static Path path(String value) {
        if (value.isEmpty()) {
            throw new TypeConversionException("an empty path ('.' names the working folder)");
        }
        return Path.of(value);
    }

    /** A whole number above zero. */
    static final class Positive implements ITypeConverter<Integer> {
        @Override
        public Integer convert(String value) {
            try {
                int n = Integer.parseInt(value);
                if (n > 0) {
                    return n;
                }
            } catch (NumberFormatException e) {
                // the message below says what was wanted
            }
            throw new TypeConversionException("'" + value + "' is not a positive number");
        }
    }
}
