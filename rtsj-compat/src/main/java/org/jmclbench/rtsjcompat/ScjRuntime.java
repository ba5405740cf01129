package org.jmclbench.rtsjcompat;

import javax.safetycritical.LaunchLevel0;
import javax.safetycritical.LaunchLevel1;
import javax.safetycritical.ManagedEventHandler;
import javax.safetycritical.Safelet;

/**
 * The entry points of this layer for a Java SE engine: launch an SCJ application and get
 * its {@link RunReport} (failure, memory areas, handler counts) instead of an exception.
 *
 * <pre>
 * RunReport r = ScjRuntime.launch(new MySafelet(), 1);
 * if (!r.succeeded()) { ... r.failure().areaName(), r.failure().getMessage() ... }
 * for (AreaUsage a : r.areas()) { ... a.name(), a.size(), a.peakBytes() ... }
 * </pre>
 */
public final class ScjRuntime {
    private ScjRuntime() {
    }

    /**
     * Runs {@code safelet} at {@code level} (0: cyclic executive, 1: handlers on their own
     * threads) to its end, as {@code new LaunchLevel0/1(safelet)} does, and returns the report;
     * a failure of the application is in the report, not thrown.
     */
    public static RunReport launch(Safelet safelet, int level) {
        if (level != 0 && level != 1) {
            throw new IllegalArgumentException("SCJ level must be 0 or 1, not " + level);
        }
        try {
            if (level == 0) {
                new LaunchLevel0(safelet);
            } else {
                new LaunchLevel1(safelet);
            }
        } catch (MissionFailure f) {
            // Already in the report.
        }
        return RunState.lastReport();
    }

    /**
     * Runs {@code safelet} as {@link #launch} does, but with the area budgets measured and not
     * enforced: a warm-up launch, so that the JVM's first-use costs (class loading, which a
     * JVM charges to whatever area is current; an SCJ VM has none) are paid before the
     * measured launch.
     */
    public static RunReport warmUp(Safelet safelet, int level) {
        RunState.enforceNext(false);
        try {
            return launch(safelet, level);
        } finally {
            RunState.enforceNext(true);
        }
    }

    /** The report of the last launch that ended in this JVM, or null. */
    public static RunReport lastReport() {
        return RunState.lastReport();
    }

    /** The live counts of {@code handler} in the launch in progress. */
    public static HandlerStats stats(ManagedEventHandler handler) {
        HandlerRuntime h = RunState.current().runtimeOf(handler);
        if (h == null) {
            throw new IllegalArgumentException("not a periodic, aperiodic or one-shot handler of this launch: " + handler);
        }
        return h.stats();
    }

    /**
     * Loads and initialises the named classes now, on the calling thread, so that the JVM's
     * class-loading allocations are not charged to the areas of the next launch (an SCJ VM
     * has its classes ready before the program starts). Call it before {@link #launch}.
     */
    public static void preload(String... classNames) {
        Preload.run(classNames);
    }

    /** Loads this layer's own classes (done by every launch; exposed for the launch's caller). */
    public static void preloadRuntime() {
        Preload.run();
    }

    /** Installs what tells the area of an arbitrary object (a verification listener); null removes it. */
    public static void installResolver(ObjectAreaResolver resolver) {
        RunState.installResolver(resolver);
    }
}
