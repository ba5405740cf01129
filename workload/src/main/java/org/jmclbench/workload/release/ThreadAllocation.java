package org.jmclbench.workload.release;

import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;

/**
 * Bytes the calling thread has allocated on the heap so far, where the runtime counts them
 * (HotSpot, OpenJ9): read by the engine's threads when they begin and end, outside the
 * measured loop, to check that the loop itself allocated nothing.
 */
final class ThreadAllocation {
    private static final com.sun.management.ThreadMXBean COUNTER = counter();

    private ThreadAllocation() {
    }

    private static com.sun.management.ThreadMXBean counter() {
        try {
            ThreadMXBean bean = ManagementFactory.getThreadMXBean();
            if (!(bean instanceof com.sun.management.ThreadMXBean)) {
                return null;
            }
            com.sun.management.ThreadMXBean c = (com.sun.management.ThreadMXBean) bean;
            if (!c.isThreadAllocatedMemorySupported()) {
                return null;
            }
            if (!c.isThreadAllocatedMemoryEnabled()) {
                c.setThreadAllocatedMemoryEnabled(true);
            }
            return c;
        } catch (RuntimeException | LinkageError e) {
            return null;
        }
    }

    /** The calling thread's allocated bytes, or -1 where the runtime does not count them. */
    static long now() {
        return COUNTER == null ? -1 : COUNTER.getThreadAllocatedBytes(Thread.currentThread().getId());
    }

    /**
     * The calling thread's allocation between {@code begin} (a {@link #now()} taken earlier)
     * and this call, net of what one reading itself allocates; -1 where unknown.
     */
    static long since(long begin) {
        long end = now();
        long again = now();
        if (begin < 0 || end < 0) {
            return -1;
        }
        return Math.max(0, (end - begin) - (again - end));
    }
}
