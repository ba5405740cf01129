package org.jmclbench.workload.shim;

import java.io.PrintStream;

/**
 * The calling thread's CPU time, for the per-job {@code cpu_ns} column: what a run's jobs read
 * before and after each job. On a JVM it is {@code release.ThreadCpuClock} (ThreadMXBean, probed
 * for allocation), on an RTSJ VM none (RTSJ 1.0.2 has no per-thread CPU clock). A clock that is
 * not {@link #usable()} is never read: {@link #now()} answers -1 at once.
 */
public interface CpuClock {
    /** The status of the clock {@code --no-cpu-time} asks for, as summary.json's engine.cpuTime says it. */
    String OFF = "off (--no-cpu-time)";

    /** CPU nanoseconds of the calling thread, or -1 when the clock is not usable. Allocation-free. */
    long now();

    /** Whether {@link #now()} gives real values. */
    boolean usable();

    /** How per-job CPU time was obtained, or why it was not (summary.json's {@code engine.cpuTime}). */
    String status();

    /** Says on {@code err} when per-job CPU time was {@code wanted} and this clock cannot give it. */
    default void warnIfNotUsable(boolean wanted, PrintStream err) {
        if (wanted && !usable()) {
            err.println("jmclbench: per-job CPU time: " + status() + "; cpu_ns is -1");
        }
    }
}
