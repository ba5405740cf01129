package org.jmclbench.tooling.runner;

import java.util.List;
import java.util.stream.Stream;

import org.jmclbench.core.policy.OverrunPolicy;

/** What an unset matrix option means; the help text quotes these. */
public final class MatrixDefaults {
    public static final List<String> PROFILES = List.of("default");
    public static final List<String> POLICIES = List.of(OverrunPolicy.SKIP.label);
    /** The engine of JVM runs; native runs are always engine {@code native}. */
    public static final List<String> ENGINES = List.of(Engines.JAVASE);
    /** The memory style; every engine has it. */
    public static final List<String> MEMORY = List.of(Engines.PREALLOCATED);
    public static final List<Integer> PARTICLES = List.of(400);
    public static final List<String> DATASETS = List.of("match-short");
    public static final int REPEAT = 1;
    public static final long SEED = 1;
    public static final double TIME_SCALE = 1.0;
    public static final String DB = "results/results.db";
    /** Timeout of one run: the replay's duration times this, plus {@link #TIMEOUT_SLACK_S}. */
    public static final double TIMEOUT_FACTOR = 3.0;
    public static final double TIMEOUT_SLACK_S = 60.0;
    /** Policies the workload knows; {@code ideal} is its {@code --ideal} mode. */
    public static final List<String> KNOWN_POLICIES = Stream.concat(Stream.of(OverrunPolicy.values()).map(p -> p.label),
            Stream.of("ideal")).toList();

    private MatrixDefaults() {
    }
}
