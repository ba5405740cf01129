package org.jmclbench.rtsjcompat;

/**
 * Releases on demand: each {@link #release()} is counted as pending, including while the
 * handler runs, and each pending release later runs handleAsyncEvent once, in release
 * order. The release times of up to {@link #CAPACITY} pending releases are kept for the
 * deadline check; beyond that (a handler far behind) a release's deadline is measured from
 * the latest kept time, which can only undercount misses.
 */
public final class AperiodicRuntime extends HandlerRuntime {
    /** Pending release times kept. */
    public static final int CAPACITY = 1024;

    private final long[] releaseTimes = new long[CAPACITY];
    private int head;
    private int stored;
    private long pending;
    private long lastTaken;

    /** An aperiodic handler. */
    public AperiodicRuntime(HandlerSetup setup) {
        super(setup, "aperiodic");
    }

    /** Releases the handler once (ignored once its mission is terminating). */
    public void release() {
        long now = time.nanoTime();
        synchronized (this) {
            if (mission != null && terminating()) {
                return;
            }
            countRelease();
            if (stored < CAPACITY) {
                releaseTimes[(head + stored) % CAPACITY] = now;
                stored++;
            }
            pending++;
            leaveIdle();
        }
    }

    @Override
    protected void releaseLoop() throws Throwable {
        while (true) {
            long release;
            synchronized (this) {
                while (pending == 0 && !terminating()) {
                    idleWait();
                }
                if (terminating()) {
                    return;
                }
                pending--;
                if (stored > 0) {
                    lastTaken = releaseTimes[head];
                    head = (head + 1) % CAPACITY;
                    stored--;
                }
                release = lastTaken;
            }
            runRelease(release);
        }
    }

    @Override
    protected synchronized long pendingReleases() {
        return pending;
    }
}
