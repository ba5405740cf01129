package javax.realtime;

import javax.safetycritical.annotate.SCJAllowed;

/** An instant: a time since the epoch of its clock. */
@SCJAllowed
public class AbsoluteTime extends HighResolutionTime<AbsoluteTime> {

    /** The epoch of the real-time clock. */
    public AbsoluteTime() {
        this(0, 0, Clock.getRealtimeClock());
    }

    /** The given instant on the real-time clock. */
    public AbsoluteTime(long millis, int nanos) {
        this(millis, nanos, Clock.getRealtimeClock());
    }

    /** A copy of {@code time}. */
    public AbsoluteTime(AbsoluteTime time) {
        this(checked(time).millis, time.nanos, time.clock);
    }

    /** The given instant on {@code clock}. */
    public AbsoluteTime(long millis, int nanos, Chronograph clock) {
        super(millis, nanos, clock == null ? Clock.getRealtimeClock() : clock);
    }

    /** The epoch of {@code clock}. */
    public AbsoluteTime(Chronograph clock) {
        this(0, 0, clock);
    }

    private static AbsoluteTime checked(AbsoluteTime time) {
        if (time == null) {
            throw new IllegalArgumentException("time is null");
        }
        return time;
    }

    /** This instant plus the given duration, in a new object. */
    public AbsoluteTime add(long millis, int nanos) {
        return add(millis, nanos, null);
    }

    /** This instant plus the given duration, written into {@code dest} (allocated when null). */
    public AbsoluteTime add(long millis, int nanos, AbsoluteTime dest) {
        AbsoluteTime d = dest == null ? new AbsoluteTime(0, 0, clock) : dest;
        long m = Math.addExact(this.millis, millis);
        d.setNormalized(m, (long) this.nanos + nanos);
        d.clock = clock;
        return d;
    }

    /** This instant plus {@code time}, in a new object. */
    public AbsoluteTime add(RelativeTime time) {
        return add(time, null);
    }

    /** This instant plus {@code time}, written into {@code dest} (allocated when null). */
    public AbsoluteTime add(RelativeTime time, AbsoluteTime dest) {
        if (time == null) {
            throw new IllegalArgumentException("time is null");
        }
        return add(time.millis, time.nanos, dest);
    }

    @Override
    public int compareTo(AbsoluteTime time) {
        return super.compareTo(time);
    }

    /** The duration from {@code time} to this instant, in a new object. */
    public RelativeTime subtract(AbsoluteTime time) {
        return subtract(time, (RelativeTime) null);
    }

    /** The duration from {@code time} to this instant, written into {@code dest} (allocated when null). */
    public RelativeTime subtract(AbsoluteTime time, RelativeTime dest) {
        if (time == null) {
            throw new IllegalArgumentException("time is null");
        }
        RelativeTime d = dest == null ? new RelativeTime(0, 0, clock) : dest;
        d.setNormalized(Math.subtractExact(millis, time.millis), (long) nanos - time.nanos);
        d.clock = clock;
        return d;
    }

    /** This instant minus {@code time}, in a new object. */
    public AbsoluteTime subtract(RelativeTime time) {
        return subtract(time, (AbsoluteTime) null);
    }

    /** This instant minus {@code time}, written into {@code dest} (allocated when null). */
    public AbsoluteTime subtract(RelativeTime time, AbsoluteTime dest) {
        if (time == null) {
            throw new IllegalArgumentException("time is null");
        }
        return add(Math.negateExact(time.millis), -time.nanos, dest);
    }
}
