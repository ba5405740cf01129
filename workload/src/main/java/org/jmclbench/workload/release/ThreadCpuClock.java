package org.jmclbench.workload.release;

import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;

import org.jmclbench.workload.shim.CpuClock;

/**
 * The calling thread's CPU time, for the per-job cpu_ns column, or -1 where the runtime cannot
 * tell it without allocating (the measured window must stay allocation-free). The javase and
 * ideal runs' clock, and the rtsj engine's on a JVM (through rtsj-compat's shim).
 */
public final class ThreadCpuClock implements CpuClock {
    private static final int PROBE_CALLS = 100_000;
    /**
     * Allocation over PROBE_CALLS calls below which the call counts as allocation-free: the
     * smallest object (16 bytes) per call would show as 1.6 MB; one-off allocations while
     * the runtime warms the path up (class initialisation, compilation) stay far below.
     */
    private static final long ONE_OFF_BYTES = 64 * 1024;

    /** The runtime's clock, or null when it is not used (usable is exactly bean != null). */
    private final ThreadMXBean bean;
    private final String status;

    private ThreadCpuClock(ThreadMXBean bean, String status) {
        this.bean = bean;
        this.status = status;
    }

    /** Probes the runtime once (before the measured window): support, then allocation. */
    public static ThreadCpuClock probe() {
        ThreadMXBean bean;
        try {
            bean = ManagementFactory.getThreadMXBean();
            if (!bean.isCurrentThreadCpuTimeSupported()) {
                return new ThreadCpuClock(null, "unsupported");
            }
            if (!bean.isThreadCpuTimeEnabled()) {
                bean.setThreadCpuTimeEnabled(true);
            }
        } catch (RuntimeException | LinkageError e) {
            return new ThreadCpuClock(null, "unavailable: " + e);
        }
        long bytes = allocatedBytesPerProbe(bean);
        if (bytes < 0) {
            // Cannot check: trust it (HotSpot and OpenJ9 read a clock), and say so.
            return new ThreadCpuClock(bean, "used (allocation not checkable)");
        }
        if (bytes > ONE_OFF_BYTES) {
            return new ThreadCpuClock(null, "disabled: allocates " + bytes + " bytes per "
                    + PROBE_CALLS + " calls");
        }
        return new ThreadCpuClock(bean, "used (allocation-free)");
    }

    /** The clock of a run: {@link #probe()}, or with {@code --no-cpu-time} (cpuTime false) none ({@link #OFF}). */
    public static ThreadCpuClock forRun(boolean cpuTime) {
        return cpuTime ? probe() : disabled(OFF);
    }

    /** A clock that always answers -1. */
    public static ThreadCpuClock disabled(String why) {
        return new ThreadCpuClock(null, why);
    }

    /**
     * Bytes the current thread allocates over {@link #PROBE_CALLS} calls of
     * getCurrentThreadCpuTime (after a shorter warm-up), net of the measuring call's own
     * allocation; -1 when the runtime has no allocation counter.
     */
    private static long allocatedBytesPerProbe(ThreadMXBean bean) {
        try {
            if (!(bean instanceof com.sun.management.ThreadMXBean)) {
                return -1;
            }
            com.sun.management.ThreadMXBean counter = (com.sun.management.ThreadMXBean) bean;
            if (!counter.isThreadAllocatedMemorySupported()) {
                return -1;
            }
            if (!counter.isThreadAllocatedMemoryEnabled()) {
                counter.setThreadAllocatedMemoryEnabled(true);
            }
            long id = Thread.currentThread().getId();
            long sink = 0;
            for (int i = 0; i < PROBE_CALLS / 10; i++) {
                sink += bean.getCurrentThreadCpuTime(); // one-off warm-up allocations, not counted
            }
            long a0 = counter.getThreadAllocatedBytes(id);
            long a1 = counter.getThreadAllocatedBytes(id);
            for (int i = 0; i < PROBE_CALLS; i++) {
                sink += bean.getCurrentThreadCpuTime();
            }
            long a2 = counter.getThreadAllocatedBytes(id);
            if (sink == Long.MIN_VALUE) {
                return -1; // keeps the loop alive; never true
            }
            return Math.max(0, (a2 - a1) - (a1 - a0));
        } catch (RuntimeException | LinkageError e) {
            return -1;
        }
    }

    /** CPU nanoseconds of the calling thread, or -1. */
    @Override
    public long now() {
        return bean != null ? bean.getCurrentThreadCpuTime() : -1;
    }

    /** Whether {@link #now()} gives real values. */
    @Override
    public boolean usable() {
        return bean != null;
    }

    /** One line for the run's summary: how per-job CPU time was obtained. */
    @Override
    public String status() {
        return status;
    }
}
