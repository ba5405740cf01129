package javax.safetycritical;

import javax.realtime.AbsoluteTime;
import javax.safetycritical.annotate.Level;
import javax.safetycritical.annotate.Phase;
import javax.safetycritical.annotate.SCJAllowed;
import org.jmclbench.rtsjcompat.HandlerRuntime;
import org.jmclbench.rtsjcompat.MissionControl;
import org.jmclbench.rtsjcompat.ScjThread;

/**
 * A mission: {@link #initialize()} creates and registers its handlers in mission memory
 * ({@link #missionMemorySize()} bytes), the handlers then run until
 * {@link #requestTermination()}, after which the handlers' and the mission's {@code cleanUp}
 * run, and the sequencer asks for the next mission.
 */
@SCJAllowed
public abstract class Mission {
    private static volatile Mission current;

    final AbsoluteTime start;
    volatile MissionSequencer sequencer;
    volatile Phase phase;
    private ManagedEventHandler[] handlers = new ManagedEventHandler[4];
    private int handlerCount;
    private volatile boolean terminationRequested;
    private volatile MissionControl control;

    /** A mission whose execute phase begins at {@code start} (null: at once). */
    @SCJAllowed
    public Mission(AbsoluteTime start) {
        this.start = start;
    }

    /** A mission whose execute phase begins at once. */
    @SCJAllowed
    public Mission() {
        this(null);
    }

    /**
     * Called after the handlers' cleanUp, in mission memory; true lets the sequencer go on
     * with its next mission, false ends the sequence. The default returns true.
     */
    @SCJAllowed(Level.SUPPORT)
    protected boolean cleanUp() {
        return true;
    }

    /** The mission being initialized, executed or cleaned up, or null. */
    @SCJAllowed
    public static Mission getMission() {
        return current;
    }

    /** The sequencer running this mission. */
    @SCJAllowed
    public MissionSequencer getSequencer() {
        return sequencer;
    }

    /** Creates and registers the mission's handlers and everything they use (in mission memory). */
    @SCJAllowed(Level.SUPPORT)
    protected abstract void initialize();

    /** The size of mission memory for this mission, in bytes. */
    @SCJAllowed(Level.SUPPORT)
    public abstract long missionMemorySize();

    /**
     * Asks every handler to end after its release in progress (a waiting aperiodic or one-shot
     * handler ends at once) and calls their {@code signalTermination()}. Returns false when
     * this call initiated termination, true when it had been requested already (as in the
     * icecap SDK).
     */
    @SCJAllowed
    public final boolean requestTermination() {
        synchronized (this) {
            if (terminationRequested) {
                return true;
            }
            terminationRequested = true;
        }
        MissionControl c = control;
        if (c != null) {
            c.requestTermination();
        }
        for (int i = 0; i < registeredCount(); i++) {
            handler(i).signalTermination();
        }
        return false;
    }

    /** Whether termination was requested (or a handler failed). */
    public final boolean terminationPending() {
        MissionControl c = control;
        return terminationRequested || (c != null && c.terminating());
    }

    // ---- for the sequencer ----

    static void setCurrent(Mission m) {
        current = m;
    }

    /** Readies the mission for a (new) run by {@code seq}. */
    synchronized void reset(MissionSequencer seq) {
        sequencer = seq;
        for (int i = 0; i < handlerCount; i++) {
            handlers[i] = null;
        }
        handlerCount = 0;
        terminationRequested = false;
        control = null;
        phase = Phase.STARTUP;
    }

    synchronized void add(ManagedEventHandler h) {
        if (handlerCount == handlers.length) {
            ScjThread.pauseAccounting();
            try {
                ManagedEventHandler[] bigger = new ManagedEventHandler[handlers.length * 2];
                System.arraycopy(handlers, 0, bigger, 0, handlerCount);
                handlers = bigger;
            } finally {
                ScjThread.resumeAccounting();
            }
        }
        handlers[handlerCount++] = h;
    }

    synchronized int registeredCount() {
        return handlerCount;
    }

    synchronized ManagedEventHandler handler(int i) {
        return handlers[i];
    }

    /** The registered handlers' runtimes (the caller pauses accounting). */
    synchronized HandlerRuntime[] runtimes() {
        HandlerRuntime[] r = new HandlerRuntime[handlerCount];
        for (int i = 0; i < handlerCount; i++) {
            r[i] = handlers[i].runtime;
        }
        return r;
    }

    /** Installs the execute phase's control; a termination requested earlier is carried over. */
    void setControl(MissionControl c) {
        control = c;
        if (terminationRequested) {
            c.requestTermination();
        }
    }
}
