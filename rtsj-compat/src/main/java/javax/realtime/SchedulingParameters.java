package javax.realtime;

import javax.safetycritical.annotate.SCJAllowed;

/** How a schedulable is chosen to run (the priority, for SCJ). */
@SCJAllowed
public abstract class SchedulingParameters implements Cloneable {
    /** For subclasses. */
    protected SchedulingParameters() {
    }

    @Override
    public Object clone() {
        try {
            return super.clone();
        } catch (CloneNotSupportedException e) {
            throw new InternalError("SchedulingParameters is Cloneable");
        }
    }
}
