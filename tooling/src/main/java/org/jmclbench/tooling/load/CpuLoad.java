package org.jmclbench.tooling.load;

import java.io.File;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.concurrent.TimeUnit;

/**
 * CPU hogs beside a run: {@code stress-ng --cpu N --timeout S} when stress-ng is on the PATH,
 * else N {@link BusyLoop} processes of our own.
 *
 * <p>The hogs never outlive the run, by four means: {@link #close()} ends them and all their
 * descendants; a shutdown hook does the same when the tool exits or is interrupted; each hog is
 * started under {@code setpriv --pdeathsig KILL} (util-linux) where available, so the kernel
 * kills it when the thread that started it dies, even by SIGKILL; and each has its own time
 * limit ({@code --timeout}, or BusyLoop's argument and its watch on its standard input) as the
 * last backstop. Because of the parent-death signal, the thread that calls {@link #start} must
 * live until {@link #close()} (the runner's run thread does).
 */
public final class CpuLoad implements AutoCloseable {
    private final List<Process> processes;
    private final String tool;
    private final Thread hook;
    private boolean closed;

    private CpuLoad(List<Process> processes, String tool) {
        this.processes = processes;
        this.tool = tool;
        this.hook = new Thread(this::end, "jmclbench-load-cleanup");
        Runtime.getRuntime().addShutdownHook(hook);
    }

    /** Starts {@code workers} CPU hogs that stop by themselves after {@code timeout} at the latest. */
    public static CpuLoad start(int workers, Duration timeout) throws IOException {
        return start(workers, timeout, true);
    }

    /** As {@link #start(int, Duration)}; {@code useStressNg} false forces our own hogs (tests). */
    static CpuLoad start(int workers, Duration timeout, boolean useStressNg) throws IOException {
        long seconds = Math.max(1, timeout.toSeconds());
        Optional<Path> stressNg = useStressNg ? onPath("stress-ng") : Optional.empty();
        List<Process> started = new ArrayList<>();
        String tool;
        try {
            if (stressNg.isPresent()) {
                tool = "stress-ng";
                started.add(spawn(List.of(stressNg.get().toString(), "--cpu", Integer.toString(workers),
                        "--timeout", seconds + "s", "--quiet")));
            } else {
                tool = "busy-loop";
                String java = ProcessHandle.current().info().command().orElse("java");
                String cp = System.getProperty("java.class.path");
                for (int i = 0; i < workers; i++) {
                    started.add(spawn(List.of(java, "-Xmx16m", "-XX:+UseSerialGC", "-cp", cp,
                            BusyLoop.class.getName(), Long.toString(seconds))));
                }
            }
        } catch (IOException | RuntimeException e) {
            started.forEach(CpuLoad::kill);
            throw e;
        }
        return new CpuLoad(started, tool);
    }

    /** {@code stress-ng} or {@code busy-loop}. */
    public String tool() {
        return tool;
    }

    /** The process ids of the hogs started (not of their children). */
    public List<Long> pids() {
        return processes.stream().map(Process::pid).toList();
    }

    /** Ends every hog and its descendants; waits (a few seconds at most) until they are gone. */
    @Override
    public synchronized void close() {
        if (closed) {
            return;
        }
        end();
        closed = true;
        try {
            Runtime.getRuntime().removeShutdownHook(hook);
        } catch (IllegalStateException e) {
            // the JVM is already shutting down: the hook runs (harmlessly) as well
        }
    }

    private void end() {
        processes.forEach(CpuLoad::kill);
    }

    private static void kill(Process p) {
        List<ProcessHandle> family = new ArrayList<>(p.toHandle().descendants().toList());
        p.destroy(); // SIGTERM: stress-ng stops its workers itself
        try {
            if (!p.waitFor(3, TimeUnit.SECONDS)) {
                p.destroyForcibly();
                p.waitFor(3, TimeUnit.SECONDS);
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            p.destroyForcibly();
        }
        for (ProcessHandle h : family) {
            if (h.isAlive()) {
                h.destroyForcibly();
            }
        }
        for (ProcessHandle h : family) {
            try {
                h.onExit().get(3, TimeUnit.SECONDS);
            } catch (Exception e) {
                // reported by the caller's checks if it still lives; nothing more to do here
            }
        }
    }

    private static Process spawn(List<String> command) throws IOException {
        List<String> cmd = new ArrayList<>();
        Optional<Path> setpriv = onPath("setpriv");
        if (setpriv.isPresent()) {
            cmd.addAll(List.of(setpriv.get().toString(), "--pdeathsig", "KILL"));
        }
        cmd.addAll(command);
        ProcessBuilder pb = new ProcessBuilder(cmd)
                .redirectOutput(ProcessBuilder.Redirect.DISCARD)
                .redirectError(ProcessBuilder.Redirect.DISCARD);
        // stdin stays a pipe: BusyLoop ends when it closes (our process died).
        return pb.start();
    }

    /** The executable {@code name} on the PATH, if any. */
    public static Optional<Path> onPath(String name) {
        String path = System.getenv("PATH");
        if (path == null) {
            return Optional.empty();
        }
        for (String dir : path.split(File.pathSeparator)) {
            if (dir.isEmpty()) {
                continue;
            }
            Path p = Path.of(dir, name);
            if (Files.isRegularFile(p) && Files.isExecutable(p)) {
                return Optional.of(p);
            }
        }
        return Optional.empty();
    }
}
