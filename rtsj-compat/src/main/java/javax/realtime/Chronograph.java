package javax.realtime;

/** Something that tells the time: the clocks of this package. */
public interface Chronograph {
    /** The offset of this clock's epoch from the real-time clock's epoch. */
    RelativeTime getEpochOffset();

    /** The resolution at which this clock is read, written into {@code dest} (allocated when null). */
    RelativeTime getQueryPrecision(RelativeTime dest);

    /** The resolution at which this clock is read. */
    RelativeTime getQueryPrecision();

    /** The current time, written into {@code dest} (allocated when null): allocation-free when given one. */
    AbsoluteTime getTime(AbsoluteTime dest);

    /** The current time in a new object. */
    AbsoluteTime getTime();
}
