package org.jmclbench.rtsjcompat;

/**
 * The execute phase of one mission: starts its handlers' threads at one common time origin,
 * carries the termination request to every handler (waking sleeping and idle ones), and lets
 * the sequencer wait until all have ended. A handler ends after its release in progress
 * completes (SCJ has no asynchronous transfer of control).
 */
public final class MissionControl extends IdleParticipant {
    private final HandlerRuntime[] handlers;
    private volatile boolean terminating;
    private int running;
    private long start = -1;

    /** The execute phase of a mission with these handlers. */
    public MissionControl(HandlerRuntime[] handlers) {
        super(RunState.current().time());
        this.handlers = handlers.clone();
    }

    /** Starts every handler with {@code missionStart} (ns) as the origin of its release times. */
    public void start(long missionStart) {
        synchronized (this) {
            running = handlers.length;
            start = missionStart;
        }
        ScjThread.pauseAccounting();
        try {
            for (HandlerRuntime h : handlers) {
                h.start(this, missionStart);
            }
        } finally {
            ScjThread.resumeAccounting();
        }
    }

    /** The time origin of the releases (ns), or -1 before {@link #start(long)}. */
    public synchronized long startTime() {
        return start;
    }

    /** Whether termination was requested. */
    public boolean terminating() {
        return terminating;
    }

    /** Asks every handler to end after its current release; false when it was already asked. */
    public boolean requestTermination() {
        synchronized (this) {
            if (terminating) {
                return false;
            }
            terminating = true;
        }
        for (HandlerRuntime h : handlers) {
            h.wakeForTermination();
        }
        return true;
    }

    /** Blocks the sequencer until every handler has ended and its thread has terminated. */
    public void awaitEnd() {
        awaitHandlersEnded();
        boolean interrupted = false;
        for (HandlerRuntime h : handlers) {
            interrupted |= ScjThread.joinThroughInterrupts(h.thread);
        }
        if (interrupted) {
            Thread.currentThread().interrupt();
        }
    }

    // The sequencer waits as an idle participant of the time source; only the handlers' ends matter here.
    private synchronized void awaitHandlersEnded() {
        while (running > 0) {
            idleWait();
        }
        endIdle();
    }

    synchronized void handlerEnded() {
        running--;
        if (running == 0) {
            leaveIdle();
        }
    }
}
