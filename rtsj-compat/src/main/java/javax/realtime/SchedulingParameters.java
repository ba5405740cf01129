package javax.realtime;

import javax.safetycritical.annotate.SCJAllowed;

/** How a schedulable is chosen to run (the priority, for SCJ). */
@SCJAllowed
public abstract class SchedulingParameters extends ShallowCloneable implements Cloneable {
    /** For subclasses. */
    protected SchedulingParameters() {
    }
}
