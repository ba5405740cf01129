package org.jmclbench.tooling.runtime;

import java.util.List;
import java.util.concurrent.TimeUnit;

/** Kills a process together with everything it started (a hung JVM may have forked helpers). */
public final class ProcessTree {
    private ProcessTree() {
    }

    /**
     * Sends SIGKILL to every process of the session {@code sid} (a run started under {@code setsid}
     * leads its own session, numbered by its pid) and waits briefly for them to end: a child that
     * outlived the run was re-parented, so it is no longer among the run's descendants, but it
     * stays in the run's session unless it left it itself. Returns how many were killed. The
     * caller's own session is never touched.
     */
    public static int killSession(long sid) {
        long own = sessionOf(ProcessHandle.current().pid());
        if (sid <= 1 || sid == own) {
            return 0;
        }
        List<ProcessHandle> members = ProcessHandle.allProcesses().filter(h -> sessionOf(h.pid()) == sid).toList();
        for (ProcessHandle h : members) {
            h.destroyForcibly();
        }
        for (ProcessHandle h : members) {
            try {
                h.onExit().get(10, TimeUnit.SECONDS);
            } catch (Exception e) {
                // a process in uninterruptible sleep ends when its I/O does; nothing more to do here
            }
        }
        return members.size();
    }

    /** The session id of process {@code pid} (field 6 of /proc/PID/stat), or -1 when it cannot be read. */
    static long sessionOf(long pid) {
        try {
            String stat = java.nio.file.Files.readString(java.nio.file.Path.of("/proc", Long.toString(pid), "stat"));
            // the command name (field 2) may hold spaces and parentheses: the fields after it follow the last ')'
            String[] f = stat.substring(stat.lastIndexOf(')') + 2).split(" ");
            return Long.parseLong(f[3]);
        } catch (java.io.IOException | RuntimeException e) {
            return -1;
        }
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
