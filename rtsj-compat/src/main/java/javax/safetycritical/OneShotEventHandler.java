package javax.safetycritical;

import javax.realtime.AbsoluteTime;
import javax.realtime.AperiodicParameters;
import javax.realtime.Clock;
import javax.realtime.ConfigurationParameters;
import javax.realtime.HighResolutionTime;
import javax.realtime.PriorityParameters;
import javax.realtime.RelativeTime;
import javax.realtime.memory.ScopeParameters;
import javax.safetycritical.annotate.Level;
import javax.safetycritical.annotate.Phase;
import javax.safetycritical.annotate.SCJAllowed;
import javax.safetycritical.annotate.SCJPhase;
import org.jmclbench.rtsjcompat.OneShotRuntime;
import org.jmclbench.rtsjcompat.RunState;
import org.jmclbench.rtsjcompat.ScjThread;

/**
 * A handler released once at a time that can be rearmed
 * ({@link #scheduleNextReleaseTime(HighResolutionTime)}, absolute or relative to now) or
 * cancelled ({@link #deschedule()}). The first release: at {@code releaseTime} (relative:
 * from the mission start; absolute: that instant); with no release time, at the mission
 * start, as in the icecap SDK.
 */
@SCJAllowed(Level.LEVEL_1)
public abstract class OneShotEventHandler extends ManagedEventHandler {
    private final OneShotRuntime oneShot;

    /** A one-shot handler named {@code name}, first released at {@code releaseTime}. */
    @SCJAllowed(Level.LEVEL_1)
    @SCJPhase(Phase.INITIALIZATION)
    public OneShotEventHandler(PriorityParameters priority, HighResolutionTime<?> releaseTime,
            AperiodicParameters release, ScopeParameters storage, ConfigurationParameters config, String name) {
        super(priority, release, storage, config, name);
        ScjThread.pauseAccounting();
        try {
            this.oneShot = new OneShotRuntime(runtimeSetup());
            this.runtime = oneShot;
        } finally {
            ScjThread.resumeAccounting();
        }
        if (releaseTime == null) {
            oneShot.scheduleAfterMissionStart(0);
        } else if (releaseTime instanceof AbsoluteTime) {
            oneShot.schedule(nanos(releaseTime));
        } else {
            oneShot.scheduleAfterMissionStart(Math.max(0, nanos(releaseTime)));
        }
    }

    /** A one-shot handler first released at {@code releaseTime}. */
    public OneShotEventHandler(PriorityParameters priority, HighResolutionTime<?> releaseTime,
            AperiodicParameters release, ScopeParameters storage, ConfigurationParameters config) {
        this(priority, releaseTime, release, storage, config, null);
    }

    /** A one-shot handler first released at the mission start. */
    public OneShotEventHandler(PriorityParameters priority, AperiodicParameters release, ScopeParameters storage,
            ConfigurationParameters config) {
        this(priority, null, release, storage, config, null);
    }

    /** Cancels the scheduled release; true when one was scheduled. */
    @SCJAllowed(Level.LEVEL_1)
    public boolean deschedule() {
        return oneShot.deschedule();
    }

    /** The scheduled release time, written into {@code dest} (allocated when null), or null when none. */
    public AbsoluteTime getNextReleaseTime(AbsoluteTime dest) {
        if (!oneShot.isScheduled()) {
            return null;
        }
        long ns = oneShot.scheduledTime();
        AbsoluteTime d = dest == null ? new AbsoluteTime(0, 0, Clock.getRealtimeClock()) : dest;
        d.set(ns / 1000000L, (int) (ns % 1000000L));
        return d;
    }

    /**
     * Rearms the handler: the next release at {@code time} (an AbsoluteTime: that instant; a
     * RelativeTime: that long from now), replacing the scheduled one. Allocation-free.
     */
    public void scheduleNextReleaseTime(HighResolutionTime<?> time) {
        if (time == null) {
            throw new IllegalArgumentException("time is null");
        }
        long at = time instanceof RelativeTime ? RunState.current().time().nanoTime() + nanos(time) : nanos(time);
        oneShot.schedule(at);
    }
}
