package org.jmclbench.workload.shim;

import java.util.Collections;
import java.util.List;

/**
 * The shim on an RTSJ VM, written against RTSJ 1.0.2 only: priorities are the VM's
 * {@code PriorityScheduler}'s, which an RTSJ VM applies by contract; handler threads belong to
 * the VM (RTSJ has no call that ends a bound handler's thread): once every event has ended they
 * are idle, and they end with the VM.
 */
final class StandardShim extends RuntimeShim {
    @Override
    public boolean prioritiesApplied() {
        return true;
    }

    @Override
    public void beforeReplay() {
    }

    @Override
    public List<String> endHandlers(long timeoutMs) {
        return Collections.emptyList();
    }
}
