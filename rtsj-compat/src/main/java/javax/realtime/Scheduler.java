package javax.realtime;

import javax.safetycritical.annotate.SCJAllowed;

/** A scheduler of schedulables; SCJ has only the {@link PriorityScheduler}. */
@SCJAllowed
public abstract class Scheduler {
    /** For subclasses. */
    protected Scheduler() {
    }
}
