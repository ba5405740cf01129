package javax.realtime;

import javax.safetycritical.annotate.SCJAllowed;

/** When a schedulable is released and its relative deadline (null: none). */
@SCJAllowed
public abstract class ReleaseParameters extends ShallowCloneable implements Cloneable {
    RelativeTime deadline;
    AsyncEventHandler missHandler;

    /** No deadline. */
    protected ReleaseParameters() {
    }

    /**
     * The given relative deadline; {@code missHandler} is kept for source compatibility but
     * never released (SCJ counts misses, see {@link org.jmclbench.rtsjcompat.HandlerStats}).
     */
    protected ReleaseParameters(RelativeTime deadline, AsyncEventHandler missHandler) {
        this.deadline = deadline == null ? null : new RelativeTime(deadline);
        this.missHandler = missHandler;
    }

    /** The relative deadline, or null when there is none. */
    public RelativeTime getDeadline() {
        return deadline;
    }

    /** The deadline-miss handler given at construction (not released by this layer). */
    public AsyncEventHandler getDeadlineMissHandler() {
        return missHandler;
    }
}
