package org.jmclbench.workload.shim;

import java.util.Collections;
import java.util.List;

/**
 * The shim on an RTSJ VM, written against RTSJ 1.0.2 only: priorities are the VM's
 * {@code PriorityScheduler}'s, which an RTSJ VM applies by contract; handler threads belong to
 * the VM (RTSJ has no call that ends a bound handler's thread): once every event has ended they
 * are idle, and they end with the VM. RTSJ 1.0.2 has no per-thread CPU clock (its cost
 * enforcement is optional and has no reading), and the VM's Java library may lack
 * {@code java.lang.management}: jobs have no CPU time ({@code cpu_ns} -1).
 */
final class StandardShim extends RuntimeShim {
    @Override
    public boolean prioritiesApplied() {
        return true;
    }

    @Override
    public void beforeReplay() {
    }

    /** The status of a run's CPU clock on an RTSJ VM, as summary.json's engine.cpuTime says it. */
    static final String UNAVAILABLE = "unavailable (RTSJ 1.0.2 has no per-thread CPU clock)";

    @Override
    public CpuClock cpuClock(boolean wanted) {
        return noCpuClock(wanted ? UNAVAILABLE : CpuClock.OFF);
    }

    @Override
    public List<String> endHandlers(long timeoutMs) {
        return Collections.emptyList();
    }
}
