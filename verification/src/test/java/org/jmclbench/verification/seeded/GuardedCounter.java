package org.jmclbench.verification.seeded;

/**
 * Seeded bugs for the static guarded-field check: a counter whose synchronized methods guard
 * {@code count} and {@code last} and own {@code tally} (they call it), and methods that forget the
 * monitor, marked VIOLATION.
 */
public final class GuardedCounter {
    private int count;
    private int last;
    // only ever touched without the monitor (one thread's own): not guarded, not reported
    private int confined;
    private final int[] slots = new int[4];
    private final Tally tally = new Tally();

    public GuardedCounter() {
        count = 0; // the constructor runs before the object is shared
    }

    public synchronized void add(int k) {
        count++;
        last = k;
        slots[0] = k;
        note(k);
    }

    /** Called only from a synchronized method: holds the monitor. */
    private void note(int k) {
        tally.record(k);
        last = k;
    }

    public synchronized int count() {
        return count;
    }

    /** Forgets the monitor (seeded). */
    public void offer(int k) {
        last = k; // VIOLATION
        count = count + 1; // VIOLATION
    }

    /** Calls the object the monitor owns without it (seeded). */
    public void recordLater(int k) {
        tally.record(k); // VIOLATION
    }

    /** Hands the owned object out: no call here, not reported. */
    public Tally tally() {
        return tally;
    }

    /** A field no synchronized method touches. */
    public void tick() {
        confined++;
    }

    /** What the counter's monitor owns: an object of no monitor of its own. */
    public static final class Tally {
        private int sum;

        public void record(int k) {
            sum += k;
        }
    }
}
