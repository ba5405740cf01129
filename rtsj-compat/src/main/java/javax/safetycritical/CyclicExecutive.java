package javax.safetycritical;

import javax.safetycritical.annotate.Level;
import javax.safetycritical.annotate.SCJAllowed;

/** A Level 0 mission: its periodic handlers run in the frames of a static cyclic schedule, on one thread. */
@SCJAllowed
public abstract class CyclicExecutive extends Mission {

    /** A cyclic executive. */
    @SCJAllowed
    public CyclicExecutive() {
        super();
    }

    /** The schedule of the registered handlers (called once at the start of the execute phase). */
    @SCJAllowed(Level.SUPPORT)
    public abstract CyclicSchedule getSchedule(PeriodicEventHandler[] handlers);
}
