package javax.realtime;

import javax.safetycritical.annotate.SCJAllowed;

/**
 * A time as milliseconds plus nanoseconds, kept normalised (both parts of one sign,
 * |nanos| below one million), measured against a clock.
 */
@SCJAllowed
public abstract class HighResolutionTime<T extends HighResolutionTime<T>> extends ShallowCloneable
        implements Comparable<T>, Cloneable {
    static final int NANOS_PER_MILLI = 1000000;

    Chronograph clock;
    long millis;
    int nanos;

    HighResolutionTime(long millis, int nanos, Chronograph clock) {
        setNormalized(millis, nanos);
        this.clock = clock;
    }

    /** Sets millis and nanos, moving whole milliseconds out of nanos and giving both parts one sign. */
    final void setNormalized(long ms, long ns) {
        long m = ms + ns / NANOS_PER_MILLI;
        long n = ns % NANOS_PER_MILLI;
        if (m > 0 && n < 0) {
            m--;
            n += NANOS_PER_MILLI;
        } else if (m < 0 && n > 0) {
            m++;
            n -= NANOS_PER_MILLI;
        }
        this.millis = m;
        this.nanos = (int) n;
    }

    /** This time in nanoseconds (saturating at the long range). */
    final long toNanos() {
        if (millis > Long.MAX_VALUE / NANOS_PER_MILLI) {
            return Long.MAX_VALUE;
        }
        if (millis < Long.MIN_VALUE / NANOS_PER_MILLI) {
            return Long.MIN_VALUE;
        }
        return millis * NANOS_PER_MILLI + nanos;
    }

    /** The clock this time is measured against. */
    public final Chronograph getChronograph() {
        return clock;
    }

    /** The clock this time is measured against, as a {@link Clock}. */
    public final Clock getClock() {
        return (Clock) clock;
    }

    /** The milliseconds part. */
    public final long getMilliseconds() {
        return millis;
    }

    /** The nanoseconds part, within (-1000000, 1000000) and of the same sign as the milliseconds. */
    public final int getNanoseconds() {
        return nanos;
    }

    /** Copies {@code time} (same class required) into this object. */
    public void set(T time) {
        if (time == null) {
            throw new IllegalArgumentException("time is null");
        }
        if (getClass() != time.getClass()) {
            throw new ClassCastException("cannot set a " + getClass().getName() + " from a " + time.getClass().getName());
        }
        HighResolutionTime<?> t = time;
        this.millis = t.millis;
        this.nanos = t.nanos;
        this.clock = t.clock;
    }

    /** Sets this time to {@code millis} milliseconds and no nanoseconds. */
    public void set(long millis) {
        this.millis = millis;
        this.nanos = 0;
    }

    /** Sets this time, normalising the two parts. */
    public void set(long millis, int nanos) {
        setNormalized(millis, nanos);
    }

    @Override
    public int hashCode() {
        return (int) (millis ^ (millis >>> 32)) * 31 + nanos;
    }

    /** Whether {@code time} denotes the same instant or duration on the same clock. */
    public boolean equals(T time) {
        if (time == null) {
            return false;
        }
        HighResolutionTime<?> t = time;
        return getClass() == t.getClass() && millis == t.millis && nanos == t.nanos && clock == t.clock;
    }

    @Override
    @SuppressWarnings("unchecked")
    public boolean equals(Object object) {
        return object instanceof HighResolutionTime && equals((T) object);
    }

    /** Orders by milliseconds, then nanoseconds; the two times must be of one class and clock. */
    @Override
    public int compareTo(T time) {
        if (time == null) {
            throw new IllegalArgumentException("time is null");
        }
        HighResolutionTime<?> t = time;
        if (getClass() != t.getClass()) {
            throw new ClassCastException("cannot compare a " + getClass().getName() + " with a " + t.getClass().getName());
        }
        if (clock != t.clock) {
            throw new IllegalArgumentException("the two times are measured against different clocks");
        }
        if (millis != t.millis) {
            return millis < t.millis ? -1 : 1;
        }
        return nanos < t.nanos ? -1 : (nanos == t.nanos ? 0 : 1);
    }

    @Override
    public String toString() {
        return "(" + millis + " ms, " + nanos + " ns)";
    }

    /**
     * Waits on {@code target} (whose monitor the caller holds) for at most {@code time}
     * (relative, or absolute on the real-time clock); false when the time ran out.
     * Not part of SCJ Level 1, which has no wait; kept for source compatibility.
     */
    public static boolean waitForObject(Object target, HighResolutionTime<?> time) throws InterruptedException {
        if (target == null || time == null) {
            throw new IllegalArgumentException("target or time is null");
        }
        long nowNs = org.jmclbench.rtsjcompat.TimeSource.current().nanoTime();
        long deadline = time instanceof AbsoluteTime ? time.toNanos() : nowNs + time.toNanos();
        long left = deadline - nowNs;
        if (left <= 0) {
            return false;
        }
        target.wait(left / NANOS_PER_MILLI, (int) (left % NANOS_PER_MILLI));
        return org.jmclbench.rtsjcompat.TimeSource.current().nanoTime() < deadline;
    }
}
