package org.jmclbench.tooling.attribution;

/**
 * One interval during which the runtime did something that can delay a job, in the run's time
 * base: nanoseconds from the run start (the release of time 0), like the job lines.
 *
 * @param kind    what happened
 * @param startNs start, ns from the run start (negative before the run started)
 * @param endNs   end, ns from the run start ({@code >= startNs}; equal for instant events)
 * @param thread  the thread it happened on, or null when it stops every thread or is unknown
 * @param detail  a short human description: collector and pause name, method, operation
 */
public record VmEvent(VmEventKind kind, long startNs, long endNs, String thread, String detail) {

    public VmEvent {
        if (endNs < startNs) {
            throw new IllegalArgumentException("event ends before it starts: " + startNs + " > " + endNs);
        }
    }

    /** Duration in ns. */
    public long durationNs() {
        return endNs - startNs;
    }

    /** The length of the overlap of this event with [from, to], 0 when they do not meet. */
    public long overlapNs(long from, long to) {
        return Math.max(0, Math.min(endNs, to) - Math.max(startNs, from));
    }

    /** True when this event and [from, to] share at least one instant. */
    public boolean meets(long from, long to) {
        return startNs <= to && endNs >= from;
    }
}
