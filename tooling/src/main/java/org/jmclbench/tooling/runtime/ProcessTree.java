package org.jmclbench.tooling.runtime;

import java.util.List;
import java.util.concurrent.TimeUnit;

/** Kills a process together with everything it started (a hung JVM may have forked helpers). */
public final class ProcessTree {
    private ProcessTree() {
    }

    /** Sends SIGKILL to the descendants first (so none is re-parented and survives), then the process. */
    public static void kill(Process process) {
        List<ProcessHandle> descendants = process.descendants().toList();
        process.toHandle().destroyForcibly();
        for (ProcessHandle h : descendants) {
            h.destroyForcibly();
        }
        try {
            process.waitFor(10, TimeUnit.SECONDS);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }
}
