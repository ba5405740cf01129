package org.jmclbench.tooling.attribution;

/** What the runtime was doing during a {@link VmEvent}; {@link #cause()} is the name stored and shown. */
public enum VmEventKind {
    /** A stop-the-world pause of the garbage collector. */
    GC_PAUSE("gc"),
    /** A safepoint (all Java threads stopped), including the time to reach it. */
    SAFEPOINT("safepoint"),
    /** A JIT compilation (runs on a compiler thread; the job runs slower code meanwhile). */
    COMPILATION("jit"),
    /** Compiled code thrown away: the job falls back to the interpreter. */
    DEOPTIMIZATION("deopt"),
    /** A class loaded by a thread. */
    CLASS_LOAD("classload"),
    /** A thread parked (LockSupport) or blocked entering a monitor. */
    THREAD_BLOCKED("lock");

    private final String cause;

    VmEventKind(String cause) {
        this.cause = cause;
    }

    /** The cause name used in attributions, metrics and the report. */
    public String cause() {
        return cause;
    }
}
