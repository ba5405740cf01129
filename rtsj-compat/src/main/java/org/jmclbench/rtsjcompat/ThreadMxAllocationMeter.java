package org.jmclbench.rtsjcompat;

import java.lang.invoke.MethodHandle;
import java.lang.invoke.MethodHandles;
import java.lang.invoke.MethodType;
import java.lang.management.ManagementFactory;

/**
 * The JVM's per-thread allocation counter. On Java 14 and later it calls
 * {@code getCurrentThreadAllocatedBytes()} through a method handle of exact type (no boxing,
 * no allocation); before, {@code getThreadAllocatedBytes(id)}, which allocates two small
 * arrays per call: that constant cost is measured once and subtracted ({@link #selfCost()}).
 * Loaded only by name from {@link AllocationMeter}, so a JVM without
 * {@code com.sun.management} never resolves it.
 */
final class ThreadMxAllocationMeter extends AllocationMeter {
    private final com.sun.management.ThreadMXBean bean;
    private final MethodHandle currentThreadBytes;
    private final long selfCost;

    ThreadMxAllocationMeter() {
        java.lang.management.ThreadMXBean b = ManagementFactory.getThreadMXBean();
        com.sun.management.ThreadMXBean c = null;
        if (b instanceof com.sun.management.ThreadMXBean) {
            c = (com.sun.management.ThreadMXBean) b;
            if (!c.isThreadAllocatedMemorySupported()) {
                c = null;
            } else if (!c.isThreadAllocatedMemoryEnabled()) {
                c.setThreadAllocatedMemoryEnabled(true);
            }
        }
        this.bean = c;
        this.currentThreadBytes = c == null ? null : currentThreadHandle(c);
        this.selfCost = c == null ? 0 : calibrate();
    }

    private static MethodHandle currentThreadHandle(com.sun.management.ThreadMXBean c) {
        try {
            MethodHandle h = MethodHandles.publicLookup().findVirtual(com.sun.management.ThreadMXBean.class,
                    "getCurrentThreadAllocatedBytes", MethodType.methodType(long.class));
            return h.bindTo(c);
        } catch (NoSuchMethodException | IllegalAccessException e) {
            return null;
        }
    }

    /** The smallest difference between two back-to-back readings: what one reading allocates. */
    private long calibrate() {
        long best = Long.MAX_VALUE;
        for (int i = 0; i < 64; i++) {
            long a = allocatedBytes();
            long b = allocatedBytes();
            best = Math.min(best, b - a);
        }
        return Math.max(0, best);
    }

    @Override
    public long allocatedBytes() {
        if (currentThreadBytes != null) {
            try {
                return (long) currentThreadBytes.invokeExact();
            } catch (Throwable t) {
                throw new IllegalStateException("reading the thread allocation counter failed", t);
            }
        }
        return bean.getThreadAllocatedBytes(Thread.currentThread().getId());
    }

    @Override
    public long selfCost() {
        return selfCost;
    }

    @Override
    public boolean measures() {
        return bean != null;
    }

    @Override
    public String name() {
        return currentThreadBytes != null ? "ThreadMXBean.getCurrentThreadAllocatedBytes"
                : "ThreadMXBean.getThreadAllocatedBytes";
    }
}
