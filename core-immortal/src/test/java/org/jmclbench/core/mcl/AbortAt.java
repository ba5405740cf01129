package org.jmclbench.core.mcl;

/**
 * A test's abort signal that requests the abort from its {@code at}-th poll on, counting the
 * polls: for the "an aborted job changes nothing" tests of every module (shared through this
 * module's test jar).
 */
public final class AbortAt implements AbortSignal {
    private final int at;
    private int polls;

    /** Requests the abort at poll {@code at} (1 = the first) and every poll after. */
    public AbortAt(int at) {
        this.at = at;
    }

    @Override
    public boolean abortRequested() {
        return ++polls >= at;
    }

    /** The polls so far. */
    public int polls() {
        return polls;
    }
}
