package javax.safetycritical;

import javax.realtime.AbsoluteTime;
import javax.realtime.Clock;
import javax.realtime.ConfigurationParameters;
import javax.realtime.HighResolutionTime;
import javax.realtime.PeriodicParameters;
import javax.realtime.PriorityParameters;
import javax.realtime.memory.ScopeParameters;
import javax.safetycritical.annotate.SCJAllowed;
import org.jmclbench.rtsjcompat.PeriodicRuntime;
import org.jmclbench.rtsjcompat.ScjThread;

/**
 * A handler released at {@code mission start + start + k * period} (absolute times, no
 * drift); the deadline defaults to the period.
 */
@SCJAllowed
public abstract class PeriodicEventHandler extends ManagedEventHandler {
    private final PeriodicRuntime periodic;
    private final PeriodicParameters releaseParameters;

    /** A periodic handler. */
    public PeriodicEventHandler(PriorityParameters priority, PeriodicParameters release, ScopeParameters storage,
            ConfigurationParameters config) {
        this(priority, release, storage, config, null);
    }

    /** A periodic handler named {@code name}. */
    public PeriodicEventHandler(PriorityParameters priority, PeriodicParameters release, ScopeParameters storage,
            ConfigurationParameters config, String name) {
        super(priority, checked(release), storage, config, name);
        this.releaseParameters = release;
        ScjThread.pauseAccounting();
        try {
            this.periodic = new PeriodicRuntime(runtimeSetup(), nanos(release.getStart()), nanos(release.getPeriod()));
            this.runtime = periodic;
        } finally {
            ScjThread.resumeAccounting();
        }
    }

    private static PeriodicParameters checked(PeriodicParameters release) {
        if (release == null) {
            throw new IllegalArgumentException("a PeriodicEventHandler needs PeriodicParameters (a period)");
        }
        return release;
    }

    private static AbsoluteTime at(long ns, AbsoluteTime dest) {
        if (ns < 0) {
            return null;
        }
        AbsoluteTime d = dest == null ? new AbsoluteTime(0, 0, Clock.getRealtimeClock()) : dest;
        d.set(0, 0);
        return d.add(ns / 1000000L, (int) (ns % 1000000L), d);
    }

    /** The time of the first release (null before the mission started). */
    @SuppressWarnings("unchecked")
    public <T extends HighResolutionTime<T>> T getActualStartTime() {
        return (T) at(periodic.firstReleaseTime(), null);
    }

    /** The time of the first release (null before the mission started). */
    public <T extends HighResolutionTime<T>> HighResolutionTime<?> getEffectiveStartTime() {
        return at(periodic.firstReleaseTime(), null);
    }

    /** The time of the last release (null before the first). */
    public AbsoluteTime getLastReleaseTime() {
        return at(periodic.lastReleaseTime(), null);
    }

    /** The time of the next release (null before the mission started). */
    public AbsoluteTime getNextReleaseTime() {
        return getNextReleaseTime(null);
    }

    /** The time of the next release, written into {@code dest} (null before the mission started). */
    public AbsoluteTime getNextReleaseTime(AbsoluteTime dest) {
        return at(periodic.nextReleaseTime(), dest);
    }

    /** The start given in the PeriodicParameters (relative to the mission start). */
    @SuppressWarnings("unchecked")
    public <T extends HighResolutionTime<T>> T getRequestedStartTime() {
        return (T) releaseParameters.getStart();
    }
}
