package org.jmclbench.scj;

import javax.realtime.AbsoluteTime;
import javax.realtime.Clock;

/**
 * Time in nanoseconds from the mission start, read from the SCJ real-time clock into a caller's
 * preallocated {@link AbsoluteTime} (one per handler: no allocation, no sharing across threads).
 * The mission start is taken at the end of {@code initialize()}, the instant from which SCJ
 * counts the handlers' relative start times.
 */
public final class MissionClock {
    private volatile long startNs;

    /** Marks now as the mission start. */
    void start(AbsoluteTime buffer) {
        startNs = absoluteNs(buffer);
    }

    /** Now, in ns from the mission start. */
    public long nowNs(AbsoluteTime buffer) {
        return absoluteNs(buffer) - startNs;
    }

    /** Sets dest to the absolute time of {@code ns} from the mission start. */
    void toAbsolute(long ns, AbsoluteTime dest) {
        long abs = startNs + ns;
        dest.set(abs / 1000000L, (int) (abs % 1000000L));
    }

    private static long absoluteNs(AbsoluteTime buffer) {
        Clock.getRealtimeClock().getTime(buffer);
        return buffer.getMilliseconds() * 1000000L + buffer.getNanoseconds();
    }
}
