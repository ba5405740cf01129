package javax.safetycritical;

import javax.realtime.AperiodicParameters;
import javax.realtime.ConfigurationParameters;
import javax.realtime.PriorityParameters;
import javax.realtime.memory.ScopeParameters;
import javax.safetycritical.annotate.Level;
import javax.safetycritical.annotate.Phase;
import javax.safetycritical.annotate.SCJAllowed;
import javax.safetycritical.annotate.SCJPhase;
import org.jmclbench.rtsjcompat.AperiodicRuntime;
import org.jmclbench.rtsjcompat.ScjThread;

/**
 * A handler released by {@link #release()}: a release that arrives while the handler runs
 * is kept pending, and each pending release later runs {@link #handleAsyncEvent()} once.
 */
@SCJAllowed(Level.LEVEL_1)
public abstract class AperiodicEventHandler extends ManagedEventHandler {
    private final AperiodicRuntime aperiodic;

    /** An aperiodic handler. */
    public AperiodicEventHandler(PriorityParameters priority, AperiodicParameters release, ScopeParameters storage,
            ConfigurationParameters config) {
        this(priority, release, storage, config, null);
    }

    /** An aperiodic handler named {@code name}. */
    @SCJAllowed(Level.LEVEL_1)
    @SCJPhase(Phase.INITIALIZATION)
    protected AperiodicEventHandler(PriorityParameters priority, AperiodicParameters release, ScopeParameters storage,
            ConfigurationParameters config, String name) {
        super(priority, checked(release), storage, config, name);
        ScjThread.pauseAccounting();
        try {
            this.aperiodic = new AperiodicRuntime(runtimeSetup());
            this.runtime = aperiodic;
        } finally {
            ScjThread.resumeAccounting();
        }
    }

    private static AperiodicParameters checked(AperiodicParameters release) {
        if (release == null) {
            throw new IllegalArgumentException("release (AperiodicParameters) is null");
        }
        return release;
    }

    /** Releases this handler once; allocation-free; ignored once the mission terminates. */
    @SCJAllowed
    public final void release() {
        aperiodic.release();
    }
}
