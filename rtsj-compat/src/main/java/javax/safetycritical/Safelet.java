package javax.safetycritical;

import javax.safetycritical.annotate.AllocationContext;
import javax.safetycritical.annotate.Level;
import javax.safetycritical.annotate.Phase;
import javax.safetycritical.annotate.SCJAllowed;
import javax.safetycritical.annotate.SCJMayAllocate;
import javax.safetycritical.annotate.SCJMaySelfSuspend;
import javax.safetycritical.annotate.SCJPhase;

/**
 * An SCJ application: the launcher sizes immortal memory from it, calls
 * {@link #initializeApplication(String[])} and {@link #getSequencer()} in immortal memory,
 * runs the sequencer's missions, and finally calls {@link #cleanUp()} in immortal memory.
 */
@SCJAllowed
public interface Safelet {
    /** Startup error: the backing store is too small. */
    @SCJAllowed
    int INSUFFICIENT_BACKING_STORE = 17;

    /** Startup error: immortal memory is too small. */
    @SCJAllowed
    int INSUFFICIENT_IMMORTAL_MEMORY = 19;

    /** The sequencer of the application's missions (called once, in immortal memory). */
    @SCJAllowed(Level.SUPPORT)
    @SCJPhase({Phase.STARTUP})
    @SCJMayAllocate({AllocationContext.CURRENT})
    @SCJMaySelfSuspend(false)
    MissionSequencer getSequencer();

    /** The backing store of all managed memories in bytes (not enforced on a JVM). */
    @SCJAllowed(Level.SUPPORT)
    @SCJPhase({Phase.STARTUP})
    @SCJMayAllocate({})
    @SCJMaySelfSuspend(false)
    long managedMemoryBackingStoreSize();

    /** The size of immortal memory in bytes. */
    @SCJAllowed(Level.SUPPORT)
    @SCJPhase({Phase.STARTUP})
    @SCJMayAllocate({})
    @SCJMaySelfSuspend(false)
    long immortalMemorySize();

    /** Sets up the application before its sequencer is asked for (in immortal memory). */
    @SCJAllowed(Level.SUPPORT)
    @SCJPhase({Phase.STARTUP})
    @SCJMayAllocate({AllocationContext.CURRENT})
    @SCJMaySelfSuspend(true)
    void initializeApplication(String[] args);

    /** Called when startup fails for {@code cause}; true asks the launcher to go on anyway. */
    @SCJAllowed(Level.SUPPORT)
    @SCJPhase({Phase.STARTUP})
    @SCJMayAllocate({AllocationContext.CURRENT})
    @SCJMaySelfSuspend(false)
    boolean handleStartupError(int cause, long val);

    /** Called after the last mission, in immortal memory. */
    @SCJAllowed(Level.SUPPORT)
    @SCJPhase({Phase.CLEANUP})
    @SCJMayAllocate({AllocationContext.CURRENT})
    @SCJMaySelfSuspend(false)
    void cleanUp();
}
