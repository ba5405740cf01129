package javax.safetycritical;

import javax.safetycritical.annotate.Level;
import javax.safetycritical.annotate.SCJAllowed;

/** The SCJ priority scheduler: priorities 1 to 100 (see {@link javax.realtime.PriorityScheduler}). */
@SCJAllowed(Level.LEVEL_1)
public class PriorityScheduler extends javax.realtime.PriorityScheduler {
    private static final PriorityScheduler INSTANCE = new PriorityScheduler();

    PriorityScheduler() {
    }

    /** The scheduler. */
    @SCJAllowed(Level.LEVEL_1)
    public static PriorityScheduler instance() {
        return INSTANCE;
    }
}
