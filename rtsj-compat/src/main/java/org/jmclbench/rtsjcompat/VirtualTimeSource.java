package org.jmclbench.rtsjcompat;

/**
 * Virtual time: the clock stands still while any participating thread can run, and jumps
 * to the earliest sleeper's deadline when every participant is asleep or idle. A run is
 * then a function of the program alone, not of the machine's speed: what Java PathFinder
 * needs, and what deterministic tests use. Everything is guarded by this object's monitor;
 * the runtime's own monitors are always taken before it, never after.
 */
public final class VirtualTimeSource extends TimeSource {
    private static final int MAX_SLEEPERS = 64;

    private final ScjThread[] sleepers = new ScjThread[MAX_SLEEPERS];
    private long now;
    private int participants;
    private int idle;
    private int sleeping;

    /** Virtual time starting at {@code start} ns. */
    public VirtualTimeSource(long start) {
        this.now = start;
    }

    @Override
    public String name() {
        return "virtual";
    }

    @Override
    public synchronized long nanoTime() {
        return now;
    }

    /** Advances the clock by hand (tests), waking the sleepers whose time has come. */
    public synchronized void advanceTo(long time) {
        if (time > now) {
            now = time;
            notifyAll();
        }
    }

    @Override
    public synchronized boolean sleepUntil(ScjThread self, long deadline) {
        int slot = addSleeper(self);
        self.sleepDeadline = deadline;
        try {
            while (true) {
                if (self.wakeRequested) {
                    self.wakeRequested = false;
                    return false;
                }
                if (now >= deadline) {
                    return true;
                }
                advanceIfAllWait();
                if (now >= deadline) {
                    return true;
                }
                try {
                    wait();
                } catch (InterruptedException e) {
                    return false;
                }
            }
        } finally {
            sleepers[slot] = null;
            sleeping--;
        }
    }

    private int addSleeper(ScjThread self) {
        for (int i = 0; i < MAX_SLEEPERS; i++) {
            if (sleepers[i] == null) {
                sleepers[i] = self;
                sleeping++;
                return i;
            }
        }
        throw new IllegalStateException("more than " + MAX_SLEEPERS + " threads sleep at once");
    }

    /**
     * Jumps to the earliest deadline when no participant can run. A sleeper whose deadline
     * has come or that was woken counts as runnable even before it re-takes this monitor.
     */
    private void advanceIfAllWait() {
        if (sleeping == 0 || sleeping + idle < participants) {
            return;
        }
        long earliest = Long.MAX_VALUE;
        for (int i = 0; i < MAX_SLEEPERS; i++) {
            ScjThread t = sleepers[i];
            if (t != null) {
                if (t.wakeRequested || t.sleepDeadline <= now) {
                    return;
                }
                if (t.sleepDeadline < earliest) {
                    earliest = t.sleepDeadline;
                }
            }
        }
        now = earliest;
        notifyAll();
    }

    @Override
    public synchronized void wake(ScjThread thread) {
        thread.wakeRequested = true;
        notifyAll();
    }

    @Override
    public synchronized void threadStarted() {
        participants++;
    }

    @Override
    public synchronized void threadEnded() {
        participants--;
        advanceIfAllWait();
    }

    @Override
    public synchronized void enterIdle() {
        idle++;
        advanceIfAllWait();
    }

    @Override
    public synchronized void leaveIdle() {
        idle--;
    }
}
