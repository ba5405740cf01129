package org.jmclbench.tooling.runner;

import java.nio.file.Path;
import java.util.concurrent.Callable;

import org.jmclbench.tooling.runtime.RuntimeDiscovery;

import picocli.CommandLine.Command;
import picocli.CommandLine.IModelTransformer;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

/** Runs a matrix of runtimes x profiles x engines x memory styles x policies x particles x datasets x repetitions. */
@Command(name = "matrix", mixinStandardHelpOptions = true,
        header = "Runs a matrix of configurations into the results store (resumable).", sortOptions = false,
        description = {"Runs a matrix of runtimes x profiles x engines x memory styles x policies x particles x datasets "
                + "x load scenarios x repetitions, each run a fresh "
                + "process with a timeout, into a SQLite database (raw run folders beside it under runs/). Rerunning the same "
                + "command resumes: runs already in the database are skipped. Lists take commas and repeats. "
                + "Exit code 0 when the matrix completed (failed runs are recorded and listed), 2 for bad input (nothing runs)."},
        footer = {"", "Example: matrix --runtimes temurin-25,native --java /opt/jdk/bin/java --profiles g1,zgc --policies skip,terminate \\",
                "           --particles 100,400,1600 --datasets match-short --repeat 3 --db results/results.db",
                "Matrix file (--matrix): 'key = value' lines, keys are these long options without dashes, e.g.",
                "  runtimes = temurin-25, native", "  engines = javase, scj", "  particles = 100, 400, 1600",
                "Options on the command line replace the file's values."},
        modelTransformer = MatrixCommand.Settings.class)
public final class MatrixCommand implements Callable<Integer> {

    @Spec
    CommandSpec commandSpec;

    @Option(names = "--matrix", paramLabel = "FILE", description = "read settings from a matrix file (see below)")
    Path matrixFile;
    // Every matrix setting follows as an option (Settings), then:
    @Option(names = "--retry-failed", description = "also rerun runs recorded as failed or timed out (unsupported ones stay)")
    boolean retryFailed;
    @Option(names = "--dry-run", description = "print the planned runs in order and stop")
    boolean dryRun;

    /** Adds one option per matrix setting, in the settings' order. */
    static final class Settings implements IModelTransformer {
        @Override
        public CommandSpec transform(CommandSpec command) {
            return SettingOptions.add(command, 1, MatrixOptions.KEYS);
        }
    }

    @Override
    public Integer call() throws Exception {
        MatrixSpec spec = toSpec();
        String command = "jmclbench matrix " + String.join(" ", commandSpec.commandLine().getParseResult().originalArgs());
        return MatrixSession.execute(spec, command, System.out, RuntimeDiscovery::discover).exitCode();
    }

    MatrixSpec toSpec() {
        MatrixSpec spec = new MatrixSpec();
        if (matrixFile != null) {
            MatrixFile.read(matrixFile, spec);
        }
        SettingOptions.apply(commandSpec, spec);
        spec.retryFailed = retryFailed;
        spec.dryRun = dryRun;
        return spec;
    }
}
