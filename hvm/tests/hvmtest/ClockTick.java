package hvmtest;

import javax.realtime.AbsoluteTime;

import vm.POSIX64BitMachineFactory;
import vm.RealtimeClock;
import vm.VMTest;

/**
 * Patch 05: the VM's 1 ms clock (what SCJ releases are timed by) keeps up with CLOCK_MONOTONIC:
 * over 2 s of VM time it may be off by at most 1%.
 */
public class ClockTick {
    /** CLOCK_MONOTONIC in nanoseconds (ClockTick.c). */
    static native long monotonicNanos();

    public static void main(String[] args) {
        POSIX64BitMachineFactory machine = new POSIX64BitMachineFactory();
        RealtimeClock clock = RealtimeClock.getRealtimeClock();
        AbsoluteTime now = new AbsoluteTime();
        clock.awaitTick();
        clock.getCurrentTime(now);
        long vmStart = now.getMilliseconds();
        long realStart = monotonicNanos();
        long vmElapsed;
        do {
            clock.awaitTick();
            clock.getCurrentTime(now);
            vmElapsed = now.getMilliseconds() - vmStart;
        } while (vmElapsed < 2000);
        long realElapsedMs = (monotonicNanos() - realStart) / 1000000;
        machine.stopSystemTick();
        long drift = realElapsedMs - vmElapsed;
        VMTest.markResult(drift > 20 || drift < -20);
    }
}
