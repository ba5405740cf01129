package javax.safetycritical;

import javax.realtime.ConfigurationParameters;
import javax.realtime.PriorityParameters;
import javax.realtime.memory.ScopeParameters;
import javax.safetycritical.annotate.AllocationContext;
import javax.safetycritical.annotate.Level;
import javax.safetycritical.annotate.Phase;
import javax.safetycritical.annotate.SCJAllowed;
import javax.safetycritical.annotate.SCJMayAllocate;
import javax.safetycritical.annotate.SCJMaySelfSuspend;
import javax.safetycritical.annotate.SCJPhase;
import org.jmclbench.rtsjcompat.Area;
import org.jmclbench.rtsjcompat.HandlerRuntime;
import org.jmclbench.rtsjcompat.MissionControl;
import org.jmclbench.rtsjcompat.RunState;
import org.jmclbench.rtsjcompat.ScjThread;
import org.jmclbench.rtsjcompat.TimeSource;

/**
 * Runs missions one after another: for each mission from {@link #getNextMission()} (called
 * in the fresh mission memory), initialize in mission memory, execute (the handlers on their
 * threads until termination), cleanUp in mission memory, then empty mission memory. Mission
 * memory's size is the sequencer's {@code maxInitialArea} until the first mission sets it
 * with {@link Mission#missionMemorySize()}. A failure anywhere ends the sequence.
 */
@SCJAllowed
public abstract class MissionSequencer extends ManagedEventHandler {
    final MissionMemory missionMemory;
    private volatile boolean sequenceTerminated;
    private volatile Mission currentMission;

    /** A sequencer named {@code name}, created in immortal memory by the Safelet. */
    @SCJAllowed
    @SCJPhase({Phase.STARTUP, Phase.INITIALIZATION})
    @SCJMaySelfSuspend(false)
    @SCJMayAllocate({AllocationContext.CURRENT, AllocationContext.INNER, AllocationContext.OUTER})
    public MissionSequencer(PriorityParameters priority, ScopeParameters storage, ConfigurationParameters config,
            String name) {
        super(priority, null, storage, config, name);
        RunState run = RunState.current();
        ScjThread.pauseAccounting();
        try {
            this.missionMemory = new MissionMemory(run.newArea("MissionMemory", Area.MISSION,
                    storage.getMaxInitialArea(), run.immortal()));
        } finally {
            ScjThread.resumeAccounting();
        }
    }

    /** A sequencer. */
    @SCJAllowed
    @SCJPhase({Phase.STARTUP, Phase.INITIALIZATION})
    public MissionSequencer(PriorityParameters priority, ScopeParameters storage, ConfigurationParameters config) {
        this(priority, storage, config, null);
    }

    /** The next mission to run, or null to end the sequence (called in mission memory). */
    @SCJAllowed(Level.SUPPORT)
    @SCJPhase({Phase.STARTUP, Phase.INITIALIZATION, Phase.CLEANUP})
    protected abstract Mission getNextMission();

    /** Runs the sequence of missions to its end (called by the launcher, on its thread). */
    @Override
    @SCJAllowed(Level.SUPPORT)
    public final void handleAsyncEvent() {
        RunState run = RunState.current();
        ScjThread t = ScjThread.self();
        Area area = missionMemory.bookkeeping();
        while (!sequenceTerminated && !run.failed()) {
            Mission m;
            try {
                t.enter(area);
                try {
                    m = getNextMission();
                } finally {
                    t.exit();
                }
            } catch (Throwable e) {
                run.fail(getName() + ".getNextMission", e);
                break;
            }
            if (m == null) {
                break;
            }
            boolean next = runMission(m, run, t, area);
            area.empty();
            if (!next) {
                break;
            }
        }
        currentMission = null;
    }

    private boolean runMission(Mission m, RunState run, ScjThread t, Area area) {
        m.reset(this);
        currentMission = m;
        Mission.setCurrent(m);
        try {
            area.resize(m.missionMemorySize());
            m.phase = Phase.INITIALIZATION;
            t.enter(area);
            try {
                m.initialize();
            } finally {
                t.exit();
            }
        } catch (Throwable e) {
            run.fail(label(m) + ".initialize", e);
        }
        if (!run.failed()) {
            m.phase = Phase.RUN;
            try {
                execute(m, run, t);
            } catch (Throwable e) {
                run.fail(label(m) + " execute", e);
            }
        }
        m.phase = Phase.CLEANUP;
        boolean next = false;
        try {
            t.enter(area);
            try {
                for (int i = 0; i < m.registeredCount(); i++) {
                    m.handler(i).cleanUp();
                }
                next = m.cleanUp();
            } finally {
                t.exit();
            }
        } catch (Throwable e) {
            run.fail(label(m) + ".cleanUp", e);
            next = false;
        }
        Mission.setCurrent(null);
        currentMission = null;
        return next;
    }

    private static String label(Mission m) {
        String s = m.getClass().getSimpleName();
        return s.isEmpty() ? m.getClass().getName() : s;
    }

    private void execute(Mission m, RunState run, ScjThread t) {
        MissionControl control;
        HandlerRuntime[] runtimes;
        ScjThread.pauseAccounting();
        try {
            runtimes = run.level() == 0 ? new HandlerRuntime[0] : m.runtimes();
            control = new MissionControl(runtimes);
        } finally {
            ScjThread.resumeAccounting();
        }
        m.setControl(control);
        TimeSource time = run.time();
        if (m.start != null) {
            long at = nanos(m.start);
            while (time.nanoTime() < at && !m.terminationPending()) {
                time.sleepUntil(t, at);
            }
        }
        if (run.level() == 0) {
            CyclicExecutor.run(m, t, missionMemory.bookkeeping(), time);
            return;
        }
        if (m instanceof CyclicExecutive) {
            throw new IllegalStateException("a CyclicExecutive is a Level 0 mission: launch it with LaunchLevel0");
        }
        control.start(time.nanoTime());
        control.awaitEnd();
    }

    /** Ends the sequence: the current mission is asked to terminate and no other follows. */
    @Override
    @SCJAllowed(Level.SUPPORT)
    public final void signalTermination() {
        sequenceTerminated = true;
        Mission m = currentMission;
        if (m != null) {
            m.requestTermination();
        }
    }

    /** Called by the launcher after the sequence ended, in immortal memory. */
    @Override
    public void cleanUp() {
    }
}
