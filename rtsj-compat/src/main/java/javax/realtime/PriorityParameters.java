package javax.realtime;

import javax.safetycritical.annotate.SCJAllowed;

/** A fixed priority, in the range of {@link PriorityScheduler} (higher runs first). */
@SCJAllowed
public class PriorityParameters extends SchedulingParameters {
    private int priority;

    /** The given priority; the affinity is ignored (the OS places the threads). */
    public PriorityParameters(int priority, Affinity affinity) {
        this.priority = priority;
    }

    /** The given priority. */
    public PriorityParameters(int priority) {
        this(priority, null);
    }

    /** The priority. */
    public int getPriority() {
        return priority;
    }

    /** Changes the priority (takes effect at the next mission start). */
    public void setPriority(int value) {
        this.priority = value;
    }
}
