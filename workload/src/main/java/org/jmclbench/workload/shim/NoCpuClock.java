package org.jmclbench.workload.shim;

/** A {@link CpuClock} that never reads a clock: every job's CPU time is -1, for the reason it keeps. */
final class NoCpuClock implements CpuClock {
    private final String status;

    NoCpuClock(String status) {
        this.status = status;
    }

    @Override
    public long now() {
        return -1;
    }

    @Override
    public boolean usable() {
        return false;
    }

    @Override
    public String status() {
        return status;
    }
}
