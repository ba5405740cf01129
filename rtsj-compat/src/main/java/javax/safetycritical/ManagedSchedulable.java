package javax.safetycritical;

import javax.realtime.Schedulable;
import javax.safetycritical.annotate.Level;
import javax.safetycritical.annotate.Phase;
import javax.safetycritical.annotate.SCJAllowed;
import javax.safetycritical.annotate.SCJPhase;

/** A schedulable whose life is bounded by its mission: registered in initialize, cleaned up after. */
@SCJAllowed
public interface ManagedSchedulable extends Schedulable {
    /** Called in the mission's cleanup phase, in mission memory. */
    @SCJAllowed(Level.SUPPORT)
    void cleanUp();

    /** Adds this schedulable to its mission (only registered ones run). */
    @SCJPhase(Phase.INITIALIZATION)
    void register();

    /** Called when the mission is asked to terminate. */
    @SCJAllowed(Level.SUPPORT)
    void signalTermination();
}
