package javax.realtime;

/**
 * A processing group's budget (RTSJ 1.0.2): accepted and kept for source compatibility; this
 * layer enforces no cost budget, so the values have no effect.
 */
public class ProcessingGroupParameters extends ShallowCloneable implements Cloneable {
    private final HighResolutionTime<?> start;
    private final RelativeTime period;
    private final RelativeTime cost;
    private final RelativeTime deadline;
    private final AsyncEventHandler overrunHandler;
    private final AsyncEventHandler missHandler;

    /** The group's start, period, cost, deadline and handlers (not enforced here). */
    public ProcessingGroupParameters(HighResolutionTime<?> start, RelativeTime period, RelativeTime cost,
            RelativeTime deadline, AsyncEventHandler overrunHandler, AsyncEventHandler missHandler) {
        this.start = start;
        this.period = period;
        this.cost = cost;
        this.deadline = deadline;
        this.overrunHandler = overrunHandler;
        this.missHandler = missHandler;
    }

    public HighResolutionTime<?> getStart() {
        return start;
    }

    public RelativeTime getPeriod() {
        return period;
    }

    public RelativeTime getCost() {
        return cost;
    }

    public RelativeTime getDeadline() {
        return deadline;
    }

    public AsyncEventHandler getCostOverrunHandler() {
        return overrunHandler;
    }

    public AsyncEventHandler getDeadlineMissHandler() {
        return missHandler;
    }
}
