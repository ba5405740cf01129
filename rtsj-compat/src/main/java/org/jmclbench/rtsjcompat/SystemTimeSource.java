package org.jmclbench.rtsjcompat;

import java.util.concurrent.locks.LockSupport;

/**
 * Real time: {@code System.nanoTime()}, and sleeps to an absolute time with
 * {@code LockSupport.parkNanos} (nanosecond resolution, unlike {@code Thread.sleep} and
 * {@code Object.wait}, which round to milliseconds on Java 8). Re-parking after an early
 * return recomputes the remaining time from the absolute deadline, so no drift accumulates.
 */
public final class SystemTimeSource extends TimeSource {

    @Override
    public String name() {
        return "system";
    }

    @Override
    public long nanoTime() {
        return System.nanoTime();
    }

    @Override
    public boolean sleepUntil(ScjThread self, long deadline) {
        while (true) {
            if (self.wakeRequested) {
                self.wakeRequested = false;
                return false;
            }
            if (Thread.interrupted()) {
                return false;
            }
            long left = deadline - System.nanoTime();
            if (left <= 0) {
                return true;
            }
            LockSupport.parkNanos(this, left);
        }
    }

    @Override
    public void wake(ScjThread thread) {
        thread.wakeRequested = true;
        LockSupport.unpark(thread);
    }
}
