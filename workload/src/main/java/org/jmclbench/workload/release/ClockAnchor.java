package org.jmclbench.workload.release;

import java.lang.management.ManagementFactory;

/**
 * Ties the run's time base (System.nanoTime) to the wall clock and to the JVM's start, so that
 * the tooling can place JFR events (wall-clock instants) and GC log lines (timenanos or
 * uptime) on the jobs' timeline after the run: summary.json's {@code engine.clock}
 * (docs/FORMATS.md section 4).
 *
 * <p>Taken just before the measured run, outside the measured window: one wall-clock reading
 * between two nanoTime readings, whose midpoint is the nanoTime of that wall-clock instant.
 * On Java 9+ the wall clock has microsecond resolution; on Java 8, milliseconds.
 */
public final class ClockAnchor {
    private final long nanoTime;
    private final long epochNs;

    private ClockAnchor(long nanoTime, long epochNs) {
        this.nanoTime = nanoTime;
        this.epochNs = epochNs;
    }

    /** Reads both clocks now. */
    public static ClockAnchor now() {
        long before = System.nanoTime();
        java.time.Instant wall = java.time.Instant.now();
        long after = System.nanoTime();
        return new ClockAnchor(before + (after - before) / 2,
                wall.getEpochSecond() * 1_000_000_000L + wall.getNano());
    }

    /** Sets the facts' {@code clock} for a run whose time 0 is {@code runStartNanoTime}. */
    void stampRunStart(JavaSeFacts facts, long runStartNanoTime) {
        facts.runStartEpochNs = epochNs + (runStartNanoTime - nanoTime);
        facts.runStartNanoTime = runStartNanoTime;
        try {
            facts.jvmStartEpochMs = ManagementFactory.getRuntimeMXBean().getStartTime();
        } catch (RuntimeException e) {
            // left at -1: uptime-stamped logs cannot be placed
        } catch (LinkageError e) {
            // the same on runtimes without java.lang.management
        }
    }
}
