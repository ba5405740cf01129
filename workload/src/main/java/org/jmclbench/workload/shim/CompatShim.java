package org.jmclbench.workload.shim;

import java.util.List;

import org.jmclbench.rtsjcompat.Atc;
import org.jmclbench.rtsjcompat.RtsjRuntime;
import org.jmclbench.rtsjcompat.ScjLauncher;

/**
 * The shim on a JVM: rtsj-compat's runtime (the one class of the engines that names it, left
 * out of {@code ant rtsj-engine}'s build for an RTSJ VM). Created by name from {@link RuntimeShim}.
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

    /** Polls of {@link Atc#primeDelivery}: enough for the JIT's profile of the delivery branch. */
    private static final int PRIMING_POLLS = 20_000;

    @Override
    public void beforeAborts() {
        Atc.primeDelivery(PRIMING_POLLS);
    }

    @Override
    public List<String> endHandlers(long timeoutMs) {
        return RtsjRuntime.stopHandlers(timeoutMs);
    }
}
