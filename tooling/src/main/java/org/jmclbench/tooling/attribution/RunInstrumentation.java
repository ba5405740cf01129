package org.jmclbench.tooling.attribution;

import java.io.IOException;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;

import org.jmclbench.tooling.cli.BadUsageException;
import org.jmclbench.tooling.load.LoadScenario;
import org.jmclbench.tooling.load.LoadSession;
import org.jmclbench.tooling.load.LoadSettings;

/**
 * What the runner adds around one workload process for attribution and load: the event
 * capture flags, the load (started here, ended by {@link #close()}), the workload options of
 * the load, and afterwards the run's {@link AttributionData}. One object per run, used with
 * try-with-resources on the thread that waits for the run (see {@link org.jmclbench.tooling.load.CpuLoad}).
 *
 * @param jvm whether the runtime under test is a JVM (the native one takes no allocation load)
 */
public record RunInstrumentation(EventCapture capture, LoadSession load, boolean jvm) implements AutoCloseable {

    /**
     * Why a run cannot run under a load scenario, or null when it can: the {@code alloc} part is a
     * thread of the Java SE engine's release loop, so the native runtime and the other engines (scj,
     * rtsj, which would ignore it and still record it) have no {@code alloc} or {@code mixed}.
     *
     * @param javaSeEngine whether the run is the Java SE engine on a JVM
     */
    public static String unsupported(boolean javaSeEngine, LoadScenario scenario) {
        return !javaSeEngine && scenario.alloc()
                ? "load " + scenario.label() + ": the allocation load runs only in the Java SE engine (javase on a JVM)" : null;
    }

    /**
     * Prepares the capture in {@code runFolder} (the runner's {@code runs/<run_key>/}) and starts
     * the load's CPU hogs, which stop by themselves shortly after {@code runTimeout} at the latest.
     *
     * @param javaMajor the JVM's feature version, or 0 for the native runtime
     */
    public static RunInstrumentation start(int javaMajor, LoadScenario scenario, LoadSettings settings, Path runFolder,
                                           Duration runTimeout) throws IOException {
        boolean jvm = javaMajor > 0;
        EventCapture capture = jvm ? JfrFlags.forJava(javaMajor, runFolder)
                : new EventCapture(EventCapture.Mode.NONE, List.of(), null);
        return new RunInstrumentation(capture, LoadSession.start(scenario, settings, runTimeout), jvm);
    }

    /** JVM flags: the event capture. */
    public List<String> jvmArgs() {
        return capture.jvmArgs();
    }

    /** Workload options: the load scenario's name and, on a JVM, its allocation load. */
    public List<String> workloadArgs() {
        return jvm ? load.workloadArgs() : List.of();
    }

    /** Ends the load's processes. */
    @Override
    public void close() {
        load.close();
    }

    /**
     * The attribution of the finished run in {@code runFolder}: the store's rows. Never fails
     * the run: a run whose events cannot be read is attributed from its job lines alone.
     */
    public static AttributionData attribute(Path runFolder) throws IOException, BadUsageException {
        return AttributionData.of(runFolder);
    }
}
