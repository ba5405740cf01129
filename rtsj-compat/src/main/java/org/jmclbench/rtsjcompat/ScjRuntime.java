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

    /** Installs what tells the area of an arbitrary object (a verification listener); null removes it. */
    public static void installResolver(ObjectAreaResolver resolver) {
        RunState.installResolver(resolver);
    }
}
