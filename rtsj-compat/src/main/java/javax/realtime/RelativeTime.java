package javax.realtime;

import javax.safetycritical.annotate.SCJAllowed;

/** A duration, measured against a clock. */
@SCJAllowed
public class RelativeTime extends HighResolutionTime<RelativeTime> {

    /** Zero on the real-time clock. */
    public RelativeTime() {
        this(0, 0);
    }

    /** The given duration on the real-time clock. */
    public RelativeTime(long millis, int nanos) {
        this(millis, nanos, Clock.getRealtimeClock());
    }

    /** Zero on {@code clock}. */
    public RelativeTime(Chronograph clock) {
        this(0, 0, clock);
    }

    /** The given duration on {@code clock}. */
    public RelativeTime(long millis, int nanos, Chronograph clock) {
        super(millis, nanos, clock == null ? Clock.getRealtimeClock() : clock);
    }

    /** A copy of {@code time}. */
    public RelativeTime(RelativeTime time) {
        this(checked(time).millis, time.nanos, time.clock);
    }

    private static RelativeTime checked(RelativeTime time) {
        if (time == null) {
            throw new IllegalArgumentException("time is null");
        }
        return time;
    }

    @Override
    public Object clone() {
        return new RelativeTime(this);
    }

    /** This duration plus the given one, in a new object. */
    public RelativeTime add(long millis, int nanos) {
        return add(millis, nanos, null);
    }

    /** This duration plus {@code time}, in a new object. */
    public RelativeTime add(RelativeTime time) {
        return add(time, null);
    }

    /** This duration plus the given one, written into {@code dest} (allocated when null). */
    public RelativeTime add(long millis, int nanos, RelativeTime dest) {
        RelativeTime d = dest == null ? new RelativeTime(0, 0, clock) : dest;
        d.setNormalized(Math.addExact(this.millis, millis), (long) this.nanos + nanos);
        d.clock = clock;
        return d;
    }

    /** This duration plus {@code time}, written into {@code dest} (allocated when null). */
    public RelativeTime add(RelativeTime time, RelativeTime dest) {
        if (time == null) {
            throw new IllegalArgumentException("time is null");
        }
        return add(time.millis, time.nanos, dest);
    }

    /** This duration minus {@code time}, in a new object. */
    public RelativeTime subtract(RelativeTime time) {
        return subtract(time, null);
    }

    /** This duration minus {@code time}, written into {@code dest} (allocated when null). */
    public RelativeTime subtract(RelativeTime time, RelativeTime dest) {
        if (time == null) {
            throw new IllegalArgumentException("time is null");
        }
        return add(Math.negateExact(time.millis), -time.nanos, dest);
    }

    @Override
    public int compareTo(RelativeTime time) {
        return super.compareTo(time);
    }
}
