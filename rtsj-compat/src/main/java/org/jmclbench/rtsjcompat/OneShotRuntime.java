package org.jmclbench.rtsjcompat;

/**
 * One release at a scheduled absolute time, rearmed by {@link #schedule(long)} (also from
 * within its own release) and cancelled by {@link #deschedule()}. Rescheduling a sleeping
 * handler wakes it so that it sleeps to the new time instead.
 */
public final class OneShotRuntime extends HandlerRuntime {
    private boolean scheduled;
    private long releaseAt;
    private boolean initialPending;
    private long initialOffset;

    /** A one-shot handler with no release scheduled. */
    public OneShotRuntime(HandlerSetup setup) {
        super(setup, "oneshot");
    }

    /** Schedules the first release {@code offset} ns after the mission start. */
    public synchronized void scheduleAfterMissionStart(long offset) {
        initialPending = true;
        initialOffset = offset;
        scheduled = false;
    }

    @Override
    protected synchronized void prepare(long missionStart) {
        if (initialPending) {
            initialPending = false;
            releaseAt = missionStart + initialOffset;
            scheduled = true;
        }
    }

    /** (Re)schedules the next release at {@code absoluteTime} (ns), replacing any scheduled one. */
    public void schedule(long absoluteTime) {
        synchronized (this) {
            initialPending = false;
            releaseAt = absoluteTime;
            scheduled = true;
            leaveIdle();
        }
        ScjThread t = thread;
        if (t != null && t != Thread.currentThread()) {
            time.wake(t);
        }
    }

    /** Cancels the scheduled release; true when one was scheduled. */
    public boolean deschedule() {
        boolean was;
        synchronized (this) {
            was = scheduled || initialPending;
            scheduled = false;
            initialPending = false;
        }
        ScjThread t = thread;
        if (was && t != null && t != Thread.currentThread()) {
            time.wake(t);
        }
        return was;
    }

    /** Whether a release is scheduled. */
    public synchronized boolean isScheduled() {
        return scheduled;
    }

    /** The scheduled release time (ns); meaningful when {@link #isScheduled()}. */
    public synchronized long scheduledTime() {
        return releaseAt;
    }

    @Override
    protected void releaseLoop() throws Throwable {
        while (true) {
            long release;
            synchronized (this) {
                while (!scheduled && !terminating()) {
                    idleWait();
                }
                if (terminating()) {
                    return;
                }
                release = releaseAt;
            }
            if (!time.sleepUntil(thread, release)) {
                continue;
            }
            synchronized (this) {
                if (terminating()) {
                    return;
                }
                if (!scheduled || releaseAt != release) {
                    continue;
                }
                scheduled = false;
                countRelease();
            }
            runRelease(release);
        }
    }

    @Override
    protected synchronized long pendingReleases() {
        return scheduled && thread != null && time.nanoTime() >= releaseAt ? 1 : 0;
    }
}
