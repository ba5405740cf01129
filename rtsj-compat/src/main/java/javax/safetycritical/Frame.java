package javax.safetycritical;

import javax.realtime.RelativeTime;
import javax.safetycritical.annotate.SCJAllowed;
import org.jmclbench.rtsjcompat.Arguments;

/** One minor cycle of a Level 0 schedule: these handlers, one release each, then wait out the duration. */
@SCJAllowed
public final class Frame {
    final RelativeTime duration;
    final PeriodicEventHandler[] handlers;

    /** A frame of {@code duration} releasing {@code handlers} in order. */
    @SCJAllowed
    public Frame(RelativeTime duration, PeriodicEventHandler[] handlers) {
        if (duration == null || ManagedEventHandler.nanos(duration) <= 0) {
            throw new IllegalArgumentException("a frame needs a positive duration");
        }
        if (handlers == null) {
            throw new IllegalArgumentException("handlers is null");
        }
        this.duration = new RelativeTime(duration);
        this.handlers = Arguments.copyWithoutNulls(handlers, "a handler is null");
    }
}
