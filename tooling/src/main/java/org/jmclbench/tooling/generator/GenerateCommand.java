package org.jmclbench.tooling.generator;

import java.io.IOException;
import java.nio.file.Path;
import java.util.concurrent.Callable;

import org.jmclbench.tooling.cli.BadUsageException;

import picocli.CommandLine.Command;
import picocli.CommandLine.Option;

/** Generates a dataset with the robot simulator. */
@Command(name = "generate", mixinStandardHelpOptions = true,
        header = "Generates a dataset with the robot simulator.", sortOptions = false,
        description = {"Generates a dataset with the robot simulator: odometry.txt, laser.txt, real.txt and "
                + "dataset.properties (docs/FORMATS.md section 1). The same scenario, seed and duration give "
                + "byte-identical files.", "", "Scenarios:",
                "  match        90 s Eurobot-like match: goal points, turns, short stops",
                "  match-short  the first 20 s of the match route (the default dataset)",
                "  match-quick  the first 10 s of the match route (the dataset of quick)",
                "  stay         30 s standing still in the middle (the thesis's stay case)",
                "  figure8      60 s figure-eight around the middle",
                "  kidnap       60 s match route, carried away at 30 s with no odometry", ""},
        footer = {"", "Example: ./jmclbench generate --scenario match --seed 1 --out data/match"})
public final class GenerateCommand implements Callable<Integer> {
    /** Longest accepted duration, seconds (one hour of data is about 15 MB). */
    static final double MAX_DURATION = 3600.0;

    @Option(names = "--scenario", required = true, paramLabel = "NAME",
            description = "match, match-short, match-quick, stay, figure8 or kidnap")
    String scenario;

    @Option(names = "--seed", paramLabel = "N", defaultValue = "1",
            description = "seed of the sensor noise, missed detections and turret angle (default: ${DEFAULT-VALUE})")
    long seed;

    @Option(names = "--duration", paramLabel = "S",
            description = "seconds of data, a multiple of 0.05 (default: the scenario's)")
    Double duration;

    @Option(names = "--out", required = true, paramLabel = "DIR", description = "the dataset folder to write")
    Path out;

    @Option(names = "--force", description = "replace an existing dataset folder")
    boolean force;

    @Option(names = "--no-noise", description = "perfect sensors: no noise, no missed detections (for checks)")
    boolean noNoise;

    @Override
    public Integer call() throws BadUsageException {
        Scenario s = Scenario.byName(scenario);
        if (s == null) {
            throw BadUsageException.ofOption("--scenario",
                    "unknown scenario '" + scenario + "' (known: " + String.join(", ", Scenario.names()) + ")");
        }
        int odometryCount = odometryCount(duration == null ? s.defaultDuration() : duration);
        SensorNoise noise = noNoise ? SensorNoise.NONE : SensorNoise.DEFAULT;
        SimulatedRun run = new Simulator(Playground.thesis(), noise).run(s, seed, odometryCount);
        if (run.laser().length == 0) {
            // The workload refuses an empty laser.txt: such a dataset would be written but never run.
            throw BadUsageException.ofOption("--duration", String.format(java.util.Locale.ROOT,
                    "%.2f s of %s with seed %d has no laser event (the workload needs one); take a longer duration",
                    run.duration(), s.name(), seed));
        }
        try {
            DatasetWriter.write(run, out, force);
        } catch (IOException e) {
            // Nothing half-written is left under the name; say what the file system refused.
            throw BadUsageException.ofOption("--out", "cannot write " + out + ": " + e.getClass().getSimpleName()
                    + " " + e.getMessage());
        }
        System.out.printf("jmclbench: wrote %s: %s, seed %d, %.2f s, %d odometry and %d laser events%n", out,
                s.name(), seed, run.duration(), run.odometry().length, run.laser().length);
        return 0;
    }

    /** The number of 50 ms odometry periods in a duration, which must be a positive multiple of 0.05 s. */
    static int odometryCount(double seconds) throws BadUsageException {
        if (!(seconds > 0) || seconds > MAX_DURATION) {
            throw BadUsageException.ofOption("--duration", "must be more than 0 and at most " + MAX_DURATION + " s");
        }
        double periods = seconds * Simulator.ODOMETRY_RATE;
        long n = Math.round(periods);
        if (n < 1 || Math.abs(periods - n) > 1e-6) {
            throw BadUsageException.ofOption("--duration", "must be a multiple of the odometry period 0.05 s");
        }
        return (int) n;
    }
}
