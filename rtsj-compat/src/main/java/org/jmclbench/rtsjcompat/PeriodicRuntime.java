package org.jmclbench.rtsjcompat;

/**
 * Periodic releases at the absolute times {@code missionStart + start + k * period}: the
 * thread sleeps to each absolute time (never to a relative one, so lateness does not
 * accumulate as drift). A release that could not start before the next release time is
 * counted as late and still runs: releases are never dropped, the handler catches up.
 */
public final class PeriodicRuntime extends HandlerRuntime {
    private final long start;
    private final long period;
    private long base;
    private long started;
    private long lastRelease = -1;

    /** A periodic handler: first release {@code start} ns after the mission start, then every {@code period} ns. */
    public PeriodicRuntime(HandlerSetup setup, long start, long period) {
        super(setup, "periodic");
        if (period <= 0) {
            throw new IllegalArgumentException("a PeriodicEventHandler needs a positive period");
        }
        this.start = start;
        this.period = period;
    }

    @Override
    protected synchronized void prepare(long missionStart) {
        base = missionStart + start;
    }

    @Override
    protected void releaseLoop() throws Throwable {
        long k = 0;
        while (!terminating()) {
            long release = base + k * period;
            if (!time.sleepUntil(thread, release) || terminating()) {
                continue;
            }
            long now = time.nanoTime();
            synchronized (this) {
                countRelease();
                if (now - release >= period) {
                    countLateRelease();
                }
                started++;
                lastRelease = release;
            }
            k++;
            runRelease(release);
        }
    }

    @Override
    protected synchronized long pendingReleases() {
        if (thread == null) {
            return 0;
        }
        long now = time.nanoTime();
        if (now < base) {
            return 0;
        }
        long due = (now - base) / period + 1;
        return Math.max(0, due - started);
    }

    /** The last release time (ns), or -1 before the first. */
    public synchronized long lastReleaseTime() {
        return lastRelease;
    }

    /** The next release time (ns), or -1 before the mission started. */
    public synchronized long nextReleaseTime() {
        return thread == null ? -1 : base + started * period;
    }

    /** The first release time (ns), or -1 before the mission started. */
    public synchronized long firstReleaseTime() {
        return thread == null ? -1 : base;
    }
}
