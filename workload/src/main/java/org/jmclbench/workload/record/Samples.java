package org.jmclbench.workload.record;

import java.util.Arrays;

/**
 * A sample of nanosecond values gathered one at a time, up to a capacity known in advance (one
 * per event), for {@link Stats}. Filled after the run, never while measuring.
 */
public final class Samples {
    private final long[] values;
    private int count;

    public Samples(int capacity) {
        values = new long[capacity];
    }

    public void add(long value) {
        values[count++] = value;
    }

    public int count() {
        return count;
    }

    public Stats stats() {
        return Stats.of(values, count);
    }

    /** The values added, in ascending order (a copy). */
    public long[] sorted() {
        long[] v = Arrays.copyOf(values, count);
        Arrays.sort(v);
        return v;
    }
}
