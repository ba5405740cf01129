package org.jmclbench.rtsjcompat;

/**
 * The time seam: where the real-time clock reads and where handler threads sleep.
 *
 * <p>The default ({@code -Djmclbench.scj.time=system}) is {@link SystemTimeSource}:
 * {@code System.nanoTime()} and {@code LockSupport.parkNanos} to an absolute time; it is
 * what runs on a real JVM. {@code -Djmclbench.scj.time=virtual} selects
 * {@link VirtualTimeSource}, whose time advances only when every participating thread
 * waits (for Java PathFinder and for deterministic tests).
 *
 * <p>Protocol with the runtime (all calls allocation-free):
 * <ol>
 * <li>before a handler thread is started, its starter calls {@link #threadStarted()}; the
 *     thread calls {@link #threadEnded()} as its last action;</li>
 * <li>a thread about to wait with no deadline (an aperiodic handler with nothing pending, the
 *     sequencer waiting for its handlers) calls {@link #enterIdle()} while holding the monitor
 *     it will wait on; whoever makes it runnable again calls {@link #leaveIdle()} for it,
 *     under the same monitor (so the count is right even before the waiter wakes);</li>
 * <li>timed waits go through {@link #sleepUntil(ScjThread, long)}, cut short by
 *     {@link #wake(ScjThread)}.</li>
 * </ol>
 */
public abstract class TimeSource {
    /** The system property that selects the time source: {@code system} or {@code virtual}. */
    public static final String PROPERTY = "jmclbench.scj.time";

    private static final Installed<TimeSource> CURRENT = new Installed<TimeSource>() {
        @Override
        TimeSource choose() {
            return fromProperty(System.getProperty(PROPERTY, "system"));
        }
    };

    /** The installed time source (chosen from {@link #PROPERTY} at first use). */
    public static TimeSource current() {
        return CURRENT.get();
    }

    /** Installs a time source (tests, verification); call it before a launch, not during one. */
    public static void install(TimeSource source) {
        CURRENT.install(source, "source");
    }

    static TimeSource fromProperty(String value) {
        if ("system".equals(value)) {
            return new SystemTimeSource();
        }
        if ("virtual".equals(value)) {
            return new VirtualTimeSource(0L);
        }
        throw new IllegalArgumentException("-D" + PROPERTY + " must be system or virtual, not " + value);
    }

    /** A short name for reports ({@code system}, {@code virtual}). */
    public abstract String name();

    /** Now, in nanoseconds on a monotonic time line. */
    public abstract long nanoTime();

    /**
     * Blocks the calling thread {@code self} until {@code deadline} (absolute, on the
     * {@link #nanoTime()} line); true when the deadline was reached, false when cut short by
     * {@link #wake(ScjThread)} (or an interrupt): the caller then re-checks its state.
     */
    public abstract boolean sleepUntil(ScjThread self, long deadline);

    /** Cuts short the current or the next {@link #sleepUntil} of {@code thread}. */
    public abstract void wake(ScjThread thread);

    /** A participating thread is about to start. */
    public void threadStarted() {
    }

    /** A participating thread ends (its last call). */
    public void threadEnded() {
    }

    /** A participating thread is about to wait with no deadline. */
    public void enterIdle() {
    }

    /** A thread that was idle has been made runnable. */
    public void leaveIdle() {
    }
}
