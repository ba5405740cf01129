package javax.realtime;

import javax.safetycritical.annotate.SCJAllowed;

/**
 * Releases at {@code start + k * period} (k = 0, 1, ...), the start relative to the
 * mission's start; the deadline defaults to the period.
 */
@SCJAllowed
public class PeriodicParameters extends ReleaseParameters {
    private final RelativeTime start;
    private final RelativeTime period;

    /** Releases every {@code period} from {@code start} (null: at once), deadline = period. */
    public PeriodicParameters(RelativeTime start, RelativeTime period) {
        this(start, period, null, null);
    }

    /** Releases every {@code period} from {@code start} with the given deadline (null: the period). */
    public PeriodicParameters(RelativeTime start, RelativeTime period, RelativeTime deadline,
            AsyncEventHandler missHandler) {
        super(deadline == null ? period : deadline, missHandler);
        if (period == null || period.toNanos() <= 0) {
            throw new IllegalArgumentException("a PeriodicEventHandler needs a positive period");
        }
        if (deadline != null && deadline.toNanos() <= 0) {
            throw new IllegalArgumentException("the deadline must be positive");
        }
        this.start = start == null || start.toNanos() < 0 ? new RelativeTime(0, 0, period.clock) : new RelativeTime(start);
        this.period = new RelativeTime(period);
    }

    /** The first release's offset from the mission start. */
    public RelativeTime getStart() {
        return start;
    }

    /** The period. */
    public RelativeTime getPeriod() {
        return period;
    }
}
