package org.jmclbench.rtsjcompat;

/**
 * What one memory area received in a run: the figures of summary.json's
 * {@code memory.areas} ({@code name}, {@code size}, {@code peakBytes}) and a few more.
 */
public final class AreaUsage implements Named {
    private final String name;
    private final String kind;
    private final int depth;
    private final long size;
    private final long peakBytes;
    private final long totalBytes;
    private final long cycles;
    private final long allocatingCycles;

    AreaUsage(Area a) {
        this.name = a.name();
        this.kind = a.kindName();
        this.depth = a.depth();
        this.size = a.size();
        this.peakBytes = a.peak();
        this.totalBytes = a.total();
        this.cycles = a.cycles();
        this.allocatingCycles = a.allocatingCycles();
    }

    /** The area's stable name, e.g. {@code ImmortalMemory}, {@code MissionMemory}, {@code PrivateMemory:PredictHandler}. */
    public String name() {
        return name;
    }

    /** immortal, mission, private or nested. */
    public String kind() {
        return kind;
    }

    /** The nesting depth (immortal 0, mission 1, private 2, nested 3+). */
    public int depth() {
        return depth;
    }

    /** The budget in bytes. */
    public long size() {
        return size;
    }

    /** The most the area held at once (a private area: the largest single release). */
    public long peakBytes() {
        return peakBytes;
    }

    /** All bytes charged to the area during the run. */
    public long totalBytes() {
        return totalBytes;
    }

    /** How often the area was emptied (a private area: its releases; mission memory: missions). */
    public long cycles() {
        return cycles;
    }

    /**
     * Cycles in which something was charged (a private area: the releases that allocated). In the
     * preallocated style on HotSpot a single one can be the JIT's, not the application's (README).
     */
    public long allocatingCycles() {
        return allocatingCycles;
    }

    /** Mean bytes per cycle (per release, for a private area); 0 when never emptied. */
    public double bytesPerCycle() {
        return cycles == 0 ? 0.0 : (double) totalBytes / cycles;
    }

    @Override
    public String toString() {
        return name + " (" + kind + "): size " + size + ", peak " + peakBytes + ", total " + totalBytes + ", cycles " + cycles + " (" + allocatingCycles + " allocating)";
    }
}
