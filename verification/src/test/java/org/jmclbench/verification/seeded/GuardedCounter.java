package org.jmclbench.verification.seeded;

/**
 * Seeded bugs for the static guarded-field check: a counter whose synchronized methods guard
 * {@code count} and {@code last}, and methods that forget the monitor, marked VIOLATION.
 */
public final class GuardedCounter {
    private int count;
    private int last;
    // only ever touched without the monitor (one thread's own): not guarded, not reported
    private int confined;
    private final int[] slots = new int[4];

    public GuardedCounter() {
        count = 0; // the constructor runs before the object is shared
    }

    public synchronized void add(int k) {
        count++;
        last = k;
        slots[0] = k;
    }

    public synchronized int count() {
        return count;
    }

    /** Forgets the monitor (seeded). */
    public void offer(int k) {
        last = k; // VIOLATION
        count = count + 1; // VIOLATION
    }

    /** A field no synchronized method touches. */
    public void tick() {
        confined++;
    }
}
