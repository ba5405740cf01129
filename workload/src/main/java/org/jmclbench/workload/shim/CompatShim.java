package org.jmclbench.workload.shim;

import java.util.List;

import org.jmclbench.rtsjcompat.Atc;
import org.jmclbench.rtsjcompat.RtsjRuntime;
import org.jmclbench.rtsjcompat.ScjLauncher;
import org.jmclbench.workload.release.ThreadCpuClock;

/**
 * The shim on a JVM: rtsj-compat's runtime (the one class of the javase and rtsj engines that
 * names it; the scj engine, which also does, is left out with it of {@code ant rtsj-engine}'s
 * build for an RTSJ VM). Created by name from {@link RuntimeShim}.
 */
public final class CompatShim extends RuntimeShim {
    @Override
    public boolean prioritiesApplied() {
        return ScjLauncher.prioritiesApplied();
    }

    @Override
    public void beforeReplay() {
        RtsjRuntime.reset();
    }

    /** Rounds of {@link Atc#prime}: enough for HotSpot to compile the fire and delivery paths. */
    private static final int PRIMING_ROUNDS = 20_000;

    @Override
    public void beforeAborts() {
        Atc.prime(PRIMING_ROUNDS);
    }

    /** The javase engine's clock (ThreadMXBean, used only if its reads do not allocate). */
    @Override
    public CpuClock cpuClock(boolean wanted) {
        return ThreadCpuClock.forRun(wanted);
    }

    @Override
    public List<String> endHandlers(long timeoutMs) {
        return RtsjRuntime.stopHandlers(timeoutMs);
    }
}
