package org.jmclbench.rtsjcompat;

/** A snapshot of one handler's release counts. */
public final class HandlerStats implements Named {
    private final String name;
    private final String kind;
    private final int priority;
    private final long releases;
    private final long completed;
    private final long pending;
    private final long deadlineMisses;
    private final long lateReleases;

    HandlerStats(String name, String kind, int priority, long releases, long completed, long pending,
            long deadlineMisses, long lateReleases) {
        this.name = name;
        this.kind = kind;
        this.priority = priority;
        this.releases = releases;
        this.completed = completed;
        this.pending = pending;
        this.deadlineMisses = deadlineMisses;
        this.lateReleases = lateReleases;
    }

    /** The handler's name (given, or its class's simple name). */
    public String name() {
        return name;
    }

    /** periodic, aperiodic or oneshot. */
    public String kind() {
        return kind;
    }

    /** Its SCJ priority. */
    public int priority() {
        return priority;
    }

    /** Releases accepted (periodic: started; aperiodic: {@code release()} calls; one-shot: fired). */
    public long releases() {
        return releases;
    }

    /** Releases whose handleAsyncEvent returned. */
    public long completed() {
        return completed;
    }

    /** Releases accepted but not yet started. */
    public long pending() {
        return pending;
    }

    /** Completed releases that ended after release time + deadline. */
    public long deadlineMisses() {
        return deadlineMisses;
    }

    /** Periodic releases that started only after the next release time had passed. */
    public long lateReleases() {
        return lateReleases;
    }

    @Override
    public String toString() {
        return name + " (" + kind + ", priority " + priority + "): releases " + releases + ", completed " + completed
                + ", pending " + pending + ", deadline misses " + deadlineMisses + ", late releases " + lateReleases;
    }
}
