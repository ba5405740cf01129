package org.jmclbench.workload.load;

import org.jmclbench.workload.output.Json;

/**
 * Background allocation load inside the runtime under test (the idea of the CDx benchmark's
 * noise generator): a daemon thread allocates byte arrays at a set rate and keeps a set live
 * set, so that the collector has both garbage to reclaim and live data to trace and move.
 *
 * <p>Each allocation replaces a random slot of a ring of live objects: the replaced object
 * becomes garbage after a random lifetime, so some survive young collections and are
 * promoted, which makes old-generation work too. Sizes vary between 256 bytes and 8 KB.
 * The thread paces itself every millisecond against the target rate, so it neither bursts
 * nor falls behind silently ({@link #allocatedBytes()} tells what it achieved).
 *
 * <p>It runs beside the measured window on purpose: it is the load, not the job.
 */
public final class AllocationNoise implements Runnable {
    private static final int MIN_SIZE = 256;
    private static final int MAX_SIZE = 8192;
    private static final long PACE_NS = 1_000_000L;

    private final int mbPerSecond;
    private final int liveMb;
    private final long bytesPerSecond;
    private final Object[] live;
    private final Thread thread;
    private volatile boolean stop;
    private volatile long allocated;
    private long state = 0x9E3779B97F4A7C15L;

    private AllocationNoise(int mbPerSecond, int liveMb) {
        this.mbPerSecond = mbPerSecond;
        this.liveMb = liveMb;
        this.bytesPerSecond = mbPerSecond * 1024L * 1024L;
        long slots = liveMb * 1024L * 1024L / ((MIN_SIZE + MAX_SIZE) / 2);
        this.live = new Object[(int) Math.max(1, Math.min(Integer.MAX_VALUE - 8, slots))];
        this.thread = new Thread(this, "jmclbench-alloc-noise");
        this.thread.setDaemon(true);
    }

    /**
     * Fills the live set, then starts allocating {@code mbPerSecond} MB/s in the background.
     * Returns once the live set is in place, so that filling it is not part of the run.
     */
    public static AllocationNoise start(int mbPerSecond, int liveMb) {
        if (mbPerSecond < 1 || liveMb < 0) {
            throw new IllegalArgumentException("allocation rate must be >= 1 MB/s and live set >= 0 MB");
        }
        AllocationNoise n = new AllocationNoise(mbPerSecond, liveMb);
        if (liveMb > 0) {
            for (int i = 0; i < n.live.length; i++) {
                n.live[i] = new byte[n.nextSize()];
            }
        }
        n.thread.start();
        return n;
    }

    /** Stops the thread and waits for it (at most a second); the live set becomes garbage. */
    public void stop() {
        stop = true;
        try {
            thread.join(1000);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    /** Bytes allocated by the background thread so far (not counting the initial live set). */
    public long allocatedBytes() {
        return allocated;
    }

    /** Writes summary.json's {@code engine.loadAlloc}: the settings and what the thread achieved (call after {@link #stop}). */
    public void writeFacts(Json j) {
        j.name("loadAlloc").beginObject();
        j.name("allocMbPerS").value(mbPerSecond);
        j.name("allocLiveMb").value(liveMb);
        j.name("allocatedBytes").value(allocated);
        j.endObject();
    }

    @Override
    public void run() {
        long start = System.nanoTime();
        long done = 0;
        int slot = 0;
        while (!stop) {
            long elapsed = System.nanoTime() - start;
            long due = (long) (bytesPerSecond * (elapsed / 1e9));
            while (done < due && !stop) {
                int size = nextSize();
                byte[] b = new byte[size];
                b[0] = (byte) slot; // touched, so that it cannot be optimised away
                slot = (int) ((next() >>> 1) % live.length);
                live[slot] = b;
                done += size;
            }
            allocated = done;
            long sleepNs = PACE_NS - (System.nanoTime() - start - elapsed);
            if (sleepNs > 0) {
                try {
                    Thread.sleep(sleepNs / 1_000_000L, (int) (sleepNs % 1_000_000L));
                } catch (InterruptedException e) {
                    return;
                }
            }
        }
    }

    private int nextSize() {
        return MIN_SIZE + (int) ((next() >>> 1) % (MAX_SIZE - MIN_SIZE + 1));
    }

    /** xorshift64: cheap, allocation-free, deterministic sizes and slots. */
    private long next() {
        long x = state;
        x ^= x << 13;
        x ^= x >>> 7;
        x ^= x << 17;
        state = x;
        return x;
    }
}
