package org.jmclbench.workload.engine;

import java.io.IOException;

import org.jmclbench.workload.BadInputException;
import org.jmclbench.workload.RunFailure;
import org.jmclbench.workload.RunOptions;
import org.jmclbench.workload.UnsupportedRunException;
import org.jmclbench.workload.data.Dataset;

/**
 * One way of running a test's jobs (SPEC sections 4 and 12): the Java SE release engine, the
 * ideal run, the SCJ mission, ... The run's lifecycle is not an engine's: {@code WorkloadMain}
 * parses the options, loads the dataset, asks the engine to {@link #validate} it, begins the
 * run folder, captures the environment, calls {@link #run}, writes the engine's
 * {@link EngineResult} and commits the folder. A new engine is one class implementing this
 * and one line in {@link Engines}.
 */
public interface Engine {

    /** The {@code --engine} value and summary.json's {@code engine.kind}. */
    String name();

    /**
     * Rejects, when the command line is parsed, options this engine does not take (a memory
     * style it lacks, options of another engine), with a {@link BadInputException} naming the option.
     */
    void checkOptions(RunOptions options) throws BadInputException;

    /**
     * Rejects the dataset, or options that depend on it, before anything is written or started
     * (the SCJ mission's periodic odometry), or, with an {@link UnsupportedRunException}, a
     * configuration beyond the runtime under test's limits. Nothing to check by default.
     */
    default void validate(RunOptions options, Dataset dataset) throws BadInputException, UnsupportedRunException {
    }

    /**
     * The runtime name of the run path when {@code -j} is not given, from the running JVM's
     * ({@link RunOptions#defaultRuntimeName()}): by default that name and {@code -<engine>}, so
     * that an engine's runs never land in another engine's folders of the same JVM.
     */
    default String runtimeName(String jvmName) {
        return jvmName + "-" + name();
    }

    /**
     * The runtime name for these options: {@link #runtimeName(String)} unless an option of the
     * engine changes what runs (the rtsj engine's design).
     */
    default String runtimeName(String jvmName, RunOptions options) {
        return runtimeName(jvmName);
    }

    /**
     * Runs the test; on return every event of the result's records is done, late, skipped or
     * terminated. A failure of the runtime under test or of the benchmark is a {@link RunFailure}.
     */
    EngineResult run(EngineInput input) throws BadInputException, IOException, RunFailure;
}
