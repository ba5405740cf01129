package org.jmclbench.rtsjcompat;

import java.util.Collections;
import java.util.List;

/** The outcome of one launch: success or the failure, each area's use, each handler's counts. */
public final class RunReport {
    private final int level;
    private final boolean budgetsEnforced;
    private final MissionFailure failure;
    private final List<AreaUsage> areas;
    private final List<HandlerStats> handlers;
    private final String allocationMeter;
    private final boolean allocationMeasured;
    private final boolean prioritiesApplied;
    private final String timeSource;

    RunReport(int level, boolean budgetsEnforced, MissionFailure failure, List<AreaUsage> areas, List<HandlerStats> handlers,
            AllocationMeter meter, boolean prioritiesApplied, TimeSource time) {
        this.level = level;
        this.budgetsEnforced = budgetsEnforced;
        this.failure = failure;
        this.areas = Collections.unmodifiableList(areas);
        this.handlers = Collections.unmodifiableList(handlers);
        this.allocationMeter = meter.name();
        this.allocationMeasured = meter.measures();
        this.prioritiesApplied = prioritiesApplied;
        this.timeSource = time.name();
    }

    /** The SCJ compliance level the application was launched at (0 or 1). */
    public int level() {
        return level;
    }

    /** Whether area overflows raised OutOfMemoryError (false for {@link ScjRuntime#warmUp}). */
    public boolean budgetsEnforced() {
        return budgetsEnforced;
    }

    /** Whether the launch ran to its end with no failure. */
    public boolean succeeded() {
        return failure == null;
    }

    /** The failure, or null. */
    public MissionFailure failure() {
        return failure;
    }

    /** Every memory area of the run, in creation order (immortal first). */
    public List<AreaUsage> areas() {
        return areas;
    }

    /** The area named {@code name}, or null. */
    public AreaUsage area(String name) {
        return named(areas, name);
    }

    /** The first of {@code items} named {@code name}, or null. */
    private static <T extends Named> T named(List<T> items, String name) {
        for (T t : items) {
            if (t.name().equals(name)) {
                return t;
            }
        }
        return null;
    }

    /** Every handler of every mission, in creation order. */
    public List<HandlerStats> handlers() {
        return handlers;
    }

    /** The handler named {@code name}, or null. */
    public HandlerStats handler(String name) {
        return named(handlers, name);
    }

    /** What measured allocations ({@code none} when nothing was). */
    public String allocationMeter() {
        return allocationMeter;
    }

    /** Whether area usage was measured (false: the figures are 0 and no budget was enforced). */
    public boolean allocationMeasured() {
        return allocationMeasured;
    }

    /** Whether handler priorities reached the OS scheduler ({@link Priorities#applied()}). */
    public boolean prioritiesApplied() {
        return prioritiesApplied;
    }

    /** The time source of the run: system or virtual. */
    public String timeSource() {
        return timeSource;
    }
}
