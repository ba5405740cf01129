package javax.safetycritical;

import javax.realtime.BoundAsyncEventHandler;
import javax.realtime.ConfigurationParameters;
import javax.realtime.PriorityParameters;
import javax.realtime.RelativeTime;
import javax.realtime.ReleaseParameters;
import javax.realtime.memory.ScopeParameters;
import javax.safetycritical.annotate.Level;
import javax.safetycritical.annotate.Phase;
import javax.safetycritical.annotate.SCJAllowed;
import javax.safetycritical.annotate.SCJPhase;
import org.jmclbench.rtsjcompat.Area;
import org.jmclbench.rtsjcompat.HandlerRuntime;
import org.jmclbench.rtsjcompat.HandlerSetup;
import org.jmclbench.rtsjcompat.RunState;
import org.jmclbench.rtsjcompat.ScjThread;

/**
 * An SCJ event handler: created in its mission's initialize (in mission memory), it runs on
 * its own thread at its priority, and each release runs {@link #handleAsyncEvent()} in its
 * private memory, of {@link ScopeParameters#getMaxInitialArea()} bytes, emptied at the end of
 * the release.
 */
@SCJAllowed
public abstract class ManagedEventHandler extends BoundAsyncEventHandler implements ManagedSchedulable {
    final PriorityParameters priority;
    final ReleaseParameters release;
    final ScopeParameters storage;
    final ConfigurationParameters config;
    final String name;
    final Mission mission;
    final PrivateMemory privateMemory;
    HandlerRuntime runtime;
    boolean registered;

    ManagedEventHandler(PriorityParameters priority, ReleaseParameters release, ScopeParameters storage,
            ConfigurationParameters config, String name) {
        if (priority == null) {
            throw new IllegalArgumentException("priority is null");
        }
        if (storage == null) {
            throw new IllegalArgumentException("storage (ScopeParameters) is null");
        }
        this.priority = priority;
        this.release = release;
        this.storage = storage;
        this.config = config;
        RunState run = RunState.current();
        ScjThread.pauseAccounting();
        try {
            this.name = run.uniqueName(name != null ? name : defaultName(getClass()));
            if (this instanceof MissionSequencer) {
                this.mission = null;
                this.privateMemory = null;
            } else {
                this.mission = Mission.getMission();
                if (mission == null || mission.phase != Phase.INITIALIZATION) {
                    throw new IllegalStateException("handler " + this.name + " must be created in its mission's initialize()");
                }
                Area missionArea = mission.sequencer.missionMemory.bookkeeping();
                this.privateMemory = new PrivateMemory(run.newArea("PrivateMemory:" + this.name, Area.PRIVATE,
                        storage.getMaxInitialArea(), missionArea));
            }
        } finally {
            ScjThread.resumeAccounting();
        }
    }

    private static String defaultName(Class<?> c) {
        String s = c.getSimpleName();
        return s.isEmpty() ? c.getName() : s;
    }

    /**
     * What this handler's release machinery is made from: its name, priority, private memory,
     * the deadline of its release parameters and the backing store of its storage parameters
     * (the thread's stack: the JVM's default). Called by the subclass constructors.
     */
    final HandlerSetup runtimeSetup() {
        return new HandlerSetup(this, name, priority.getPriority(), privateMemory.bookkeeping(), deadlineOf(release),
                storage.getMaxBackingStore());
    }

    /** The deadline of {@code release} in ns, or {@link HandlerRuntime#NO_DEADLINE}. */
    static long deadlineOf(ReleaseParameters release) {
        RelativeTime d = release == null ? null : release.getDeadline();
        return d == null ? HandlerRuntime.NO_DEADLINE : nanos(d);
    }

    static long nanos(javax.realtime.HighResolutionTime<?> t) {
        return t.getMilliseconds() * 1000000L + t.getNanoseconds();
    }

    /** Called in the mission's cleanup phase, in mission memory; the default does nothing. */
    @Override
    @SCJAllowed(Level.SUPPORT)
    @SCJPhase(Phase.CLEANUP)
    public void cleanUp() {
    }

    /** Adds this handler to its mission: only registered handlers are released. */
    @Override
    @SCJAllowed
    @SCJPhase(Phase.INITIALIZATION)
    public void register() {
        if (mission == null || mission.phase != Phase.INITIALIZATION) {
            throw new IllegalStateException("register() is allowed only in the mission's initialize()");
        }
        if (!registered) {
            registered = true;
            mission.add(this);
        }
    }

    /** Called when the mission is asked to terminate; the default does nothing. */
    @Override
    @SCJAllowed(Level.SUPPORT)
    public void signalTermination() {
    }

    /** The handler's name (given, or its class's simple name; made unique in the run). */
    public String getName() {
        return name;
    }
}
