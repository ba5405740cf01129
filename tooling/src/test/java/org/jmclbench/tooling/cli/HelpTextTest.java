package org.jmclbench.tooling.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;

import org.jmclbench.tooling.Fixtures;
import org.jmclbench.tooling.Fixtures.CliResult;
import org.junit.jupiter.api.Test;

import picocli.CommandLine;

/**
 * What a newcomer reads first: {@code jmclbench --help} names every command in one whole line, and
 * each command's own {@code --help} fits an 80-column terminal without picocli's format warnings.
 * The command descriptions used to be hard-wrapped lines that picocli wrapped again, so the list
 * showed half sentences ("... with the javase and scj engines, the native").
 */
class HelpTextTest {

    /** Every command and subcommand, as its argument list ("jvm install" is two). */
    private static List<List<String>> commands() {
        List<List<String>> all = new ArrayList<>();
        collect(new CommandLine(new JmclbenchCli()), new ArrayList<>(), all);
        return all;
    }

    private static void collect(CommandLine c, List<String> path, List<List<String>> all) {
        for (Map.Entry<String, CommandLine> e : c.getSubcommands().entrySet()) {
            List<String> p = new ArrayList<>(path);
            p.add(e.getKey());
            all.add(p);
            collect(e.getValue(), p, all);
        }
    }

    @Test
    void theCommandListGivesEachCommandOneWholeLine() {
        CliResult r = Fixtures.cli("--help");
        assertEquals(0, r.exitCode(), r.err());
        List<String> lines = r.out().lines().toList();
        int first = lines.indexOf("Commands:") + 1;
        int count = new CommandLine(new JmclbenchCli()).getSubcommands().size();
        for (String line : lines.subList(first, first + count)) {
            assertTrue(line.matches("  \\S+ +\\S.*\\."), "one line ending its sentence: '" + line + "'");
        }
        assertTrue(lines.get(first + count).isBlank(), "no continuation line: " + lines.get(first + count));
        for (String launcherCommand : List.of("run", "run-native", "run-hvm", "verify", "abort-bound", "test")) {
            assertTrue(r.out().contains("\n  " + launcherCommand + " "), "the launcher's " + launcherCommand + " is named");
        }
    }

    @Test
    void everyCommandsHelpFitsEightyColumnsWithoutWarnings() {
        List<List<String>> commands = commands();
        assertTrue(commands.size() >= 13, commands.toString());
        for (List<String> command : commands) {
            List<String> args = new ArrayList<>(command);
            args.add("--help");
            CliResult r = Fixtures.cli(args.toArray(String[]::new));
            assertEquals(0, r.exitCode(), command + ": " + r.err());
            assertFalse(r.err().contains("WARN") || r.out().contains("WARN"), command + ": " + r.err() + r.out());
            for (String line : r.out().lines().toList()) {
                assertTrue(line.length() <= 80, command + ": a line over 80 columns: " + line);
            }
        }
    }
}
