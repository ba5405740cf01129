package javax.realtime;

import org.jmclbench.rtsjcompat.TimeSource;

/** The real-time clock: nanoseconds of the installed time source, split into millis and nanos. */
final class RealtimeClock extends Clock {
    static final RealtimeClock INSTANCE = new RealtimeClock();

    private RealtimeClock() {
    }

    @Override
    public RelativeTime getQueryPrecision(RelativeTime dest) {
        RelativeTime d = dest == null ? new RelativeTime(0, 0, this) : dest;
        d.setNormalized(0, 1);
        d.clock = this;
        return d;
    }

    @Override
    public AbsoluteTime getTime(AbsoluteTime dest) {
        AbsoluteTime d = dest == null ? new AbsoluteTime(0, 0, this) : dest;
        d.setNormalized(0, TimeSource.current().nanoTime());
        d.clock = this;
        return d;
    }
}
