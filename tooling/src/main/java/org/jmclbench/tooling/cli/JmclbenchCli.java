package org.jmclbench.tooling.cli;

import java.util.concurrent.Callable;

import org.jmclbench.tooling.attribution.ExplainCommand;
import org.jmclbench.tooling.doctor.DoctorCommand;
import org.jmclbench.tooling.generator.GenerateCommand;
import org.jmclbench.tooling.report.CompareCommand;
import org.jmclbench.tooling.report.ReportCommand;
import org.jmclbench.tooling.runner.CapacityCommand;
import org.jmclbench.tooling.runner.EvaluateCommand;
import org.jmclbench.tooling.runner.MatrixCommand;
import org.jmclbench.tooling.runner.QuickCommand;
import org.jmclbench.tooling.runtime.JvmCommand;
import org.jmclbench.tooling.runtime.JvmsCommand;
import org.jmclbench.tooling.store.MergeCommand;

import picocli.CommandLine;
import picocli.CommandLine.Command;

/**
 * The {@code ./jmclbench} command line. {@code run} (one test) is executed by the workload
 * itself on the runtime under test (see the launcher script); everything else lives here.
 */
@Command(name = "jmclbench", mixinStandardHelpOptions = true, versionProvider = CodeVersion.class,
        description = "Real-time Java benchmark: Monte-Carlo Localization replayed on its real timeline.",
        footer = {"", "Commands of the launcher itself (each takes --help):",
                "  run          one test on a JVM (--java PATH; --engine javase, scj or rtsj);",
                "               the thesis's line needs no word: jmclbench -j NAME -p 400 -n 1",
                "  run-native   one test on the C baseline",
                "  run-hvm      one test of the SCJ mission on the icecap HVM (docs/HVM.md)",
                "  verify       Java PathFinder and bytecode checks (SCJ mission, rtsj engine)",
                "  abort-bound  the static bound on abort latency, beside a run's measured one",
                "  test         every test of the project",
                "Exit codes: 0 success, 2 bad usage or bad input, 1 a failure of the benchmark;",
                "a run of one test exits 3 when the runtime under test cannot run it (the HVM's limits)."},
        subcommands = {GenerateCommand.class, QuickCommand.class, MatrixCommand.class, CapacityCommand.class,
                JvmsCommand.class, JvmCommand.class, DoctorCommand.class, ReportCommand.class, EvaluateCommand.class,
                CompareCommand.class, MergeCommand.class, ExplainCommand.class})
public final class JmclbenchCli implements Callable<Integer> {

    /** Exit code for bad usage or bad input. */
    public static final int EXIT_BAD_INPUT = 2;
    /** Exit code for a failure of the benchmark itself. */
    public static final int EXIT_FAILURE = 1;

    @Override
    public Integer call() {
        CommandLine.usage(this, System.out);
        return 0;
    }

    public static void main(String[] args) {
        System.exit(execute(args));
    }

    /** Runs the command line and returns the exit code (tests call this instead of main). */
    public static int execute(String... args) {
        CommandLine cli = new CommandLine(new JmclbenchCli());
        cli.registerConverter(java.nio.file.Path.class, JmclbenchCli::path);
        cli.setParameterExceptionHandler((ex, a) -> {
            System.err.println("jmclbench: " + oneLine(ex.getMessage()));
            return EXIT_BAD_INPUT;
        });
        cli.setExecutionExceptionHandler((ex, cmd, parsed) -> {
            if (ex instanceof BadUsageException) {
                System.err.println("jmclbench: " + oneLine(ex.getMessage()));
                return EXIT_BAD_INPUT;
            }
            if (ex instanceof java.io.UncheckedIOException u) {
                ex = u.getCause();
            }
            if (ex instanceof java.io.IOException || ex instanceof java.sql.SQLException) {
                // the machine failed the command (a full disk, a lost file): one line, not a stack trace
                String message = String.valueOf(ex.getMessage()).replaceAll("\\s+", " ").strip();
                System.err.println("jmclbench: " + cmd.getCommandName() + ": " + message);
                return EXIT_FAILURE;
            }
            throw ex;
        });
        return cli.execute(args);
    }

    /**
     * A path option's value. An empty one is refused: Path.of("") is the working folder, so an unset
     * variable ({@code --out "$DIR"}) wrote a report or figures there, and evaluate's document beside it.
     */
    private static java.nio.file.Path path(String value) {
        if (value.isEmpty()) {
            throw new CommandLine.TypeConversionException("an empty path ('.' names the working folder)");
        }
        return java.nio.file.Path.of(value);
    }

    /**
     * A bad-input message as the one line it must be, whatever the paths and values quoted in it
     * hold: each control character (and each Unicode line or paragraph separator) becomes its Java
     * string escape ({@code \n}, {@code \t}, {@code \r}, {@code \b}, {@code \f}, else a backslash, u
     * and four hex digits). A backslash stays as it is, so an ordinary path reads and pastes as typed.
     */
    static String oneLine(String message) {
        String m = String.valueOf(message);
        StringBuilder b = new StringBuilder(m.length());
        for (int i = 0; i < m.length(); i++) {
            char c = m.charAt(i);
            switch (c) {
                case '\n' -> b.append("\\n");
                case '\r' -> b.append("\\r");
                case '\t' -> b.append("\\t");
                case '\b' -> b.append("\\b");
                case '\f' -> b.append("\\f");
                default -> {
                    if (Character.isISOControl(c) || c == '\u2028' || c == '\u2029') {
                        b.append(String.format("\\u%04x", (int) c));
                    } else {
                        b.append(c);
                    }
                }
            }
        }
        return b.toString();
    }
}
