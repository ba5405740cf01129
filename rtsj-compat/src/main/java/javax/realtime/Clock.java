package javax.realtime;

import javax.safetycritical.annotate.SCJAllowed;

/** A clock; {@link #getRealtimeClock()} is the monotonic one every SCJ release time refers to. */
@SCJAllowed
public abstract class Clock implements Chronograph {

    /** For subclasses. */
    public Clock() {
    }

    /** The real-time clock: monotonic, read through {@link org.jmclbench.rtsjcompat.TimeSource}. */
    public static Clock getRealtimeClock() {
        return RealtimeClock.INSTANCE;
    }

    /** Zero: every clock here shares the real-time clock's epoch. */
    @Override
    public final RelativeTime getEpochOffset() {
        return new RelativeTime(0, 0, this);
    }

    @Override
    public RelativeTime getQueryPrecision() {
        return getQueryPrecision(null);
    }

    @Override
    public abstract RelativeTime getQueryPrecision(RelativeTime dest);

    /** The resolution of this clock (its query precision). */
    public RelativeTime getResolution() {
        return getQueryPrecision(null);
    }

    @Override
    public final AbsoluteTime getTime() {
        return getTime(new AbsoluteTime(0, 0, this));
    }

    @Override
    public abstract AbsoluteTime getTime(AbsoluteTime dest);
}
