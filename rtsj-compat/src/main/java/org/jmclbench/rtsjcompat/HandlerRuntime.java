package org.jmclbench.rtsjcompat;

import javax.realtime.AsyncEventHandler;

/**
 * The release machinery of one SCJ handler: its own {@link ScjThread} at its priority, the
 * release loop of its kind (subclasses), and its counts. A release runs
 * {@code handleAsyncEvent()} with the handler's private memory current; the area is emptied
 * when the release ends, and the release is a deadline miss when it ends after its release
 * time plus the relative deadline. Counters are guarded by this object's monitor, which is
 * also what an idle handler waits on; nothing here allocates once the thread runs.
 */
public abstract class HandlerRuntime extends IdleParticipant implements Runnable {
    /** No deadline. */
    public static final long NO_DEADLINE = Long.MAX_VALUE;

    private final AsyncEventHandler handler;
    private final String name;
    private final String kind;
    private final int priority;
    private final Area privateArea;
    private final long deadline;
    private final long backingStore;

    /** This handler's thread (set at mission start; read by the threads that wake it). */
    protected volatile ScjThread thread;
    /** The mission it belongs to (set at mission start). */
    protected volatile MissionControl mission;

    private long releases;
    private long completed;
    private long deadlineMisses;
    private long lateReleases;

    /** The runtime of the handler {@code setup} describes; {@code kind}: periodic, aperiodic or oneshot. */
    protected HandlerRuntime(HandlerSetup setup, String kind) {
        super(RunState.current().time());
        this.handler = setup.handler;
        this.name = setup.name;
        this.kind = kind;
        this.priority = setup.priority;
        this.privateArea = setup.privateArea;
        this.deadline = setup.deadline;
        this.backingStore = setup.backingStore;
        RunState.current().addHandler(this);
    }

    /** The handler object. */
    public final AsyncEventHandler handler() {
        return handler;
    }

    /** The handler's name. */
    public final String name() {
        return name;
    }

    /** Its private memory. */
    public final Area privateArea() {
        return privateArea;
    }

    /** periodic, aperiodic or oneshot. */
    public final String kind() {
        return kind;
    }

    /** The release loop; returns when the mission terminates. */
    protected abstract void releaseLoop() throws Throwable;

    /** Releases accepted but not started. */
    protected abstract long pendingReleases();

    /**
     * Creates and starts the thread; called by the mission sequencer at the start of the
     * execute phase ({@code missionStart}: the common time origin of the mission's releases).
     */
    final void start(MissionControl mission, long missionStart) {
        this.mission = mission;
        prepare(missionStart);
        ScjThread st = new ScjThread(this, name, Priorities.toJava(priority));
        st.setBackingStore(backingStore);
        this.thread = st;
        time.threadStarted();
        st.start();
    }

    /** Sets the time origin of the first release (called before the thread starts). */
    protected void prepare(long missionStart) {
    }

    /** Wakes the handler so that it sees the termination request. */
    protected void wakeForTermination() {
        synchronized (this) {
            leaveIdle();
        }
        ScjThread t = thread;
        if (t != null && t != Thread.currentThread()) {
            time.wake(t);
        }
    }

    @Override
    public final void run() {
        try {
            releaseLoop();
        } catch (Throwable t) {
            RunState.current().fail(name, t);
            mission.requestTermination();
        } finally {
            synchronized (this) {
                endIdle();
            }
            mission.handlerEnded();
            time.threadEnded();
        }
    }

    /** Counts a release accepted (under this monitor). */
    protected final void countRelease() {
        releases++;
    }

    /** Counts a release that started after the next release time had passed (under this monitor). */
    protected final void countLateRelease() {
        lateReleases++;
    }

    /**
     * Runs one release released at {@code releaseTime}: handleAsyncEvent in the private
     * memory, which is then charged, checked and emptied; counts completion and deadline miss.
     */
    protected final void runRelease(long releaseTime) throws Throwable {
        ScjThread t = thread;
        t.enter(privateArea);
        try {
            handler.handleAsyncEvent();
        } catch (Throwable failure) {
            // The release's own failure is the one to report; building it may itself have
            // pushed the area over its size, which would otherwise hide the cause.
            try {
                t.exit();
            } catch (Throwable alsoOverflow) {
                failure.addSuppressed(alsoOverflow);
            } finally {
                privateArea.empty();
            }
            throw failure;
        }
        try {
            t.exit();
        } finally {
            privateArea.empty();
        }
        long end = time.nanoTime();
        synchronized (this) {
            completed++;
            if (deadline != NO_DEADLINE && end - releaseTime > deadline) {
                deadlineMisses++;
            }
        }
    }

    /**
     * Runs one release on the calling thread (Level 0: the cyclic executive releases its
     * handlers itself, frame by frame).
     */
    public final void runInline(long releaseTime) throws Throwable {
        if (thread == null) {
            thread = ScjThread.self();
        }
        synchronized (this) {
            releases++;
        }
        runRelease(releaseTime);
    }

    /** Whether the mission asked its handlers to end. */
    protected final boolean terminating() {
        return mission.terminating();
    }

    /** A snapshot of the counts. */
    public final synchronized HandlerStats stats() {
        return new HandlerStats(name, kind(), priority, releases, completed, pendingReleases(), deadlineMisses,
                lateReleases);
    }
}
