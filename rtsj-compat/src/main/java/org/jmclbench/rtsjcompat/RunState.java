package org.jmclbench.rtsjcompat;

import java.util.ArrayList;
import java.util.List;

/**
 * The state of the launch in progress: its areas, its handlers and its first failure.
 * One launch runs at a time in a JVM (as on an SCJ VM, where the application is the
 * program). Internal to this layer and to the {@code javax} packages of this module.
 */
public final class RunState {
    private static RunState current;
    private static RunReport lastReport;
    private static ObjectAreaResolver resolver;

    private final int level;
    private final TimeSource time;
    private final AllocationMeter meter;
    private final List<Area> areas = new ArrayList<Area>();
    private final List<HandlerRuntime> handlers = new ArrayList<HandlerRuntime>();
    private final List<String> names = new ArrayList<String>();
    private Area immortal;
    private MissionFailure failure;

    private RunState(int level) {
        this.level = level;
        this.time = TimeSource.current();
        this.meter = AllocationMeter.current();
    }

    /** Starts the state of a new launch; IllegalStateException when one is running. */
    public static synchronized RunState begin(int level) {
        if (current != null) {
            throw new IllegalStateException("an SCJ application is already running in this JVM");
        }
        current = new RunState(level);
        return current;
    }

    /** Ends the launch and keeps its report. */
    public synchronized RunReport end() {
        RunReport r = report();
        synchronized (RunState.class) {
            lastReport = r;
            current = null;
        }
        return r;
    }

    /** The launch in progress; IllegalStateException outside one. */
    public static synchronized RunState current() {
        if (current == null) {
            throw new IllegalStateException("no SCJ application is running: start one with new LaunchLevel1(safelet)");
        }
        return current;
    }

    /** The launch in progress, or null. */
    public static synchronized RunState currentOrNull() {
        return current;
    }

    static synchronized RunReport lastReport() {
        return lastReport;
    }

    static synchronized void installResolver(ObjectAreaResolver r) {
        resolver = r;
    }

    /** The level launched (0 or 1). */
    public int level() {
        return level;
    }

    /** The time source of this launch. */
    public TimeSource time() {
        return time;
    }

    /** Creates and records an area. */
    public synchronized Area newArea(String name, int kind, long size, Area parent) {
        Area a = new Area(name, kind, size, parent);
        areas.add(a);
        if (kind == Area.IMMORTAL) {
            immortal = a;
        }
        return a;
    }

    /** Immortal memory (null before the launcher created it). */
    public synchronized Area immortal() {
        return immortal;
    }

    /** {@code base}, or {@code base#2}, {@code base#3}... when taken. */
    public synchronized String uniqueName(String base) {
        String n = base;
        for (int k = 2; names.contains(n); k++) {
            n = base + "#" + k;
        }
        names.add(n);
        return n;
    }

    synchronized void addHandler(HandlerRuntime h) {
        handlers.add(h);
    }

    /** The runtime of {@code handler}, or null. */
    public synchronized HandlerRuntime runtimeOf(Object handler) {
        for (HandlerRuntime h : handlers) {
            if (h.handler() == handler) {
                return h;
            }
        }
        return null;
    }

    /** The area of {@code object}: from the installed resolver, else a handler's mission memory; or null. */
    public Area areaOf(Object object) {
        ObjectAreaResolver r;
        synchronized (RunState.class) {
            r = resolver;
        }
        if (r != null) {
            Area a = r.areaOf(object);
            if (a != null) {
                return a;
            }
        }
        HandlerRuntime h = runtimeOf(object);
        return h == null ? null : h.privateArea().parent();
    }

    /** Records the first failure of the launch ({@code where}: a handler, initialize, cleanUp...). */
    public synchronized void fail(String where, Throwable cause) {
        if (failure == null) {
            failure = cause instanceof MissionFailure ? (MissionFailure) cause : new MissionFailure(where, cause);
        }
    }

    /** Whether something failed. */
    public synchronized boolean failed() {
        return failure != null;
    }

    private RunReport report() {
        List<AreaUsage> a = new ArrayList<AreaUsage>();
        for (Area x : areas) {
            a.add(new AreaUsage(x));
        }
        List<HandlerStats> h = new ArrayList<HandlerStats>();
        for (HandlerRuntime x : handlers) {
            h.add(x.stats());
        }
        return new RunReport(level, failure, a, h, meter, Priorities.applied(), time);
    }
}
