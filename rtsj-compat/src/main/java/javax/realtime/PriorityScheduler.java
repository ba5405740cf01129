package javax.realtime;

import javax.safetycritical.annotate.SCJAllowed;

/**
 * The fixed-priority preemptive scheduler: priorities 1 (lowest) to 100 (highest), the
 * range of the icecap SDK, so that numeric priorities in an application mean the same on
 * both. On a JVM they are mapped onto Java thread priorities (see
 * {@link org.jmclbench.rtsjcompat.Priorities}).
 */
@SCJAllowed
public abstract class PriorityScheduler extends Scheduler {
    /** The lowest priority. */
    static final int MIN = 1;
    /** The highest priority. */
    static final int MAX = 100;

    /** For subclasses. */
    protected PriorityScheduler() {
    }

    /** The scheduler (the one of {@code javax.safetycritical}). */
    public static PriorityScheduler instance() {
        return javax.safetycritical.PriorityScheduler.instance();
    }

    /** The highest priority a schedulable may have. */
    public int getMaxPriority() {
        return MAX;
    }

    /** The lowest priority a schedulable may have. */
    public int getMinPriority() {
        return MIN;
    }

    /** The middle of the range. */
    public int getNormPriority() {
        return (MIN + MAX) / 2;
    }
}
