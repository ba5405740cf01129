package org.jmclbench.tooling.runner;

import java.io.File;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicReference;
import java.util.stream.Stream;

import org.jmclbench.tooling.runtime.ProcessRunner;
import org.jmclbench.tooling.runtime.ProcessTree;
import org.jmclbench.tooling.store.RunRow;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;

/**
 * Runs one workload process, JMH-fork style: the host builds the whole command line, the child
 * gets its configuration from arguments only, its stdout and stderr go to files in the run folder,
 * a timeout kills the whole process tree, and a run counts as ok only when it exited 0 and left a
 * complete folder with a valid summary.json. Exit 3 is the workload saying that the runtime under
 * test cannot run the configuration (unsupported); anything else is that run's recorded failure.
 */
public final class ForkedRun {

    /** The summary schema this runner understands (docs/FORMATS.md section 4). */
    public static final String SUMMARY_SCHEMA = "jmclbench-run/1";
    /** The workload's exit code for a configuration the runtime under test cannot run (docs/FORMATS.md section 2). */
    static final int UNSUPPORTED_EXIT = 3;
    static final int STDERR_TAIL_LINES = 20;
    static final int STDERR_TAIL_CHARS = 4000;
    /** The largest summary.json read (a real one is about 10 KB: a few counts and quantiles per task). */
    static final long MAX_SUMMARY_BYTES = 16L * 1024 * 1024;
    /** How much of the end of stderr.txt is read for its tail. */
    static final int TAIL_READ_BYTES = 64 * 1024;

    private static final ObjectMapper JSON = new ObjectMapper();
    /** The child in progress (a run, or the aot profile's training run), killed by the shutdown hook if the runner is interrupted (Ctrl-C). */
    static final AtomicReference<Process> CURRENT = new AtomicReference<>();
    /** Set by the shutdown hook before it kills the child: a run ended then was ended by the runner, not the runtime. */
    private static volatile boolean stopping;

    static {
        Runtime.getRuntime().addShutdownHook(new Thread(() -> {
            stopping = true;
            Process p = CURRENT.get();
            if (p != null) {
                ProcessTree.kill(p);
                ProcessTree.killSession(p.pid());
            }
        }, "jmclbench-kill-run"));
    }

    private ForkedRun() {
    }

    /**
     * Runs {@code command} with its output in {@code folder} (which must exist), {@code out} being
     * where the command was told to write its run tree.
     */
    public static ForkOutcome execute(List<String> command, Path folder, Path out, double timeoutS,
                                     java.util.Map<String, String> env) throws IOException {
        return execute(command, folder, out, timeoutS, env, () -> stopping);
    }

    /** {@link #execute} with the runner's stopping flag given. */
    static ForkOutcome execute(List<String> command, Path folder, Path out, double timeoutS,
                               java.util.Map<String, String> env, java.util.function.BooleanSupplier stopping) throws IOException {
        Path stdout = folder.resolve("stdout.txt");
        Path stderr = folder.resolve("stderr.txt");
        ProcessBuilder pb = new ProcessBuilder(inOwnSession(command));
        pb.redirectInput(ProcessBuilder.Redirect.from(new File("/dev/null")));
        pb.redirectOutput(stdout.toFile());
        pb.redirectError(stderr.toFile());
        pb.environment().putAll(env);
        // A run started once the shutdown hook has run would outlive the runner in its own session.
        if (stopping.getAsBoolean()) {
            throw notStarted();
        }
        long t0 = System.nanoTime();
        Process p;
        try {
            p = pb.start();
        } catch (IOException e) {
            return new ForkOutcome(RunRow.FAILED, null, "cannot start " + command.get(0) + ": " + e.getMessage(), "", 0,
                    null, null, null);
        }
        if (!adopt(p, stopping)) {
            throw notStarted();
        }
        writePidFile(folder, p);
        boolean finished;
        try {
            finished = p.waitFor((long) Math.ceil(timeoutS * 1000), TimeUnit.MILLISECONDS);
        } catch (InterruptedException e) {
            ProcessTree.kill(p);
            Thread.currentThread().interrupt();
            throw new IOException("interrupted");
        } finally {
            if (!p.isAlive()) {
                CURRENT.set(null);
            }
        }
        if (!finished) {
            ProcessTree.kill(p);
            CURRENT.set(null);
        }
        // whatever the run left behind (a child that outlived it, re-parented) would overlap the next run
        ProcessTree.killSession(p.pid());
        double wall = (System.nanoTime() - t0) / 1e9;
        String tail = tail(stderr);
        if (!finished) {
            return new ForkOutcome(RunRow.TIMEOUT, null, String.format(java.util.Locale.ROOT,
                    "timed out after %.0f s: process tree killed", timeoutS), tail, wall, null, null, null);
        }
        int code = p.exitValue();
        String interruption = interruption(code);
        if (interruption != null) {
            // neither the runtime's failure nor a result: no row, so that a rerun runs it again
            throw new IOException("the run in progress was interrupted (" + interruption + "); it is not recorded: "
                    + "rerun the same command to resume");
        }
        String unsupported = code == UNSUPPORTED_EXIT ? unsupportedReason(tail) : null;
        if (unsupported != null) {
            return new ForkOutcome(RunRow.UNSUPPORTED, code, unsupported, tail, wall, null, null, null);
        }
        if (code != 0) {
            return new ForkOutcome(RunRow.FAILED, code, describeExit(code, tail), tail, wall, null, null, null);
        }
        Path leaf;
        try {
            leaf = findLeaf(out);
        } catch (IOException e) {
            return new ForkOutcome(RunRow.FAILED, code, e.getMessage(), tail, wall, null, null, null);
        }
        Path summaryFile = leaf.resolve("summary.json");
        long summaryBytes = Files.size(summaryFile);
        if (summaryBytes > MAX_SUMMARY_BYTES) {
            // read whole, a runaway one would take the runner's memory with it
            return new ForkOutcome(RunRow.FAILED, code, "garbage output: summary.json is " + summaryBytes
                    + " bytes, more than a summary's " + MAX_SUMMARY_BYTES, tail, wall, leaf, null, null);
        }
        String text = org.jmclbench.tooling.runtime.ProcessRunner.readText(summaryFile);
        JsonNode summary;
        try {
            summary = JSON.readTree(text);
        } catch (IOException e) {
            return new ForkOutcome(RunRow.FAILED, code, "garbage output: summary.json is not JSON ("
                    + firstLine(e.getMessage()) + ")", tail, wall, leaf, null, null);
        }
        if (summary == null || !summary.isObject() || !SUMMARY_SCHEMA.equals(summary.path("schema").asText())
                || !"complete".equals(summary.path("status").asText()) || !summary.path("tasks").isObject()) {
            return new ForkOutcome(RunRow.FAILED, code, "garbage output: summary.json is not a complete "
                    + SUMMARY_SCHEMA + " summary", tail, wall, leaf, null, null);
        }
        return new ForkOutcome(RunRow.OK, code, null, tail, wall, leaf, text, summary);
    }

    /**
     * {@code command} started by {@code setsid}, which leaves the runner's session and then runs
     * it in the same process (a child of the runner never leads a process group, so setsid does
     * not fork): the session, numbered by the run's pid, holds everything the run starts, found
     * and killed after it even when re-parented. Unchanged where setsid is not installed.
     */
    static List<String> inOwnSession(List<String> command) {
        return org.jmclbench.tooling.load.CpuLoad.onPath("setsid").map(setsid -> {
            List<String> c = new ArrayList<>(List.of(setsid.toString(), "--wait"));
            c.addAll(command);
            return c;
        }).orElse(command);
    }

    static final String PID_FILE = "runner.pid";

    /** Notes the child's pid and start time, so that a later runner can kill it if this one dies first. */
    private static void writePidFile(Path folder, Process p) {
        String started = p.toHandle().info().startInstant().map(Object::toString).orElse("");
        try {
            Files.writeString(folder.resolve(PID_FILE), p.pid() + " " + started + "\n");
        } catch (IOException ignored) {
            // only a help for cleaning up after a killed runner
        }
    }

    /**
     * Kills the process left running by a runner that was killed mid-run (SIGKILL leaves its child
     * orphaned), identified by the pid file in its run folder and checked by its start time.
     */
    public static void killOrphan(Path folder) {
        Path f = folder.resolve(PID_FILE);
        if (!Files.isRegularFile(f)) {
            return;
        }
        try {
            String[] w = Files.readString(f).strip().split(" ");
            long pid = Long.parseLong(w[0]);
            String started = w.length > 1 ? w[1] : "";
            ProcessHandle.of(pid).ifPresent(h -> {
                if (h.isAlive() && h.info().startInstant().map(Object::toString).orElse("-").equals(started)) {
                    h.descendants().forEach(ProcessHandle::destroyForcibly);
                    h.destroyForcibly();
                    h.onExit().orTimeout(10, TimeUnit.SECONDS).exceptionally(e -> h).join();
                    // and what it started in its session (only while the pid is surely the run's:
                    // an old pid file's number may lead someone else's session by now)
                    ProcessTree.killSession(pid);
                }
            });
        } catch (IOException | RuntimeException ignored) {
            // a damaged pid file: nothing to kill
        }
    }

    /**
     * Makes {@code p} (a run, or the aot profile's training run, just started) the child the shutdown
     * hook kills; when the runner is already stopping, kills it here instead and returns false. The hook
     * sets its flag and then reads {@link #CURRENT}: it kills p, or this sees the flag.
     */
    static void adopt(Process p) {
        adopt(p, () -> stopping);
    }

    static boolean adopt(Process p, java.util.function.BooleanSupplier stopping) {
        CURRENT.set(p);
        if (!stopping.getAsBoolean()) {
            return true;
        }
        ProcessTree.kill(p);
        ProcessTree.killSession(p.pid());
        CURRENT.set(null);
        return false;
    }

    private static IOException notStarted() {
        return new IOException("the runner is stopping; the next run was not started: rerun the same command to resume");
    }

    /** The one complete run folder (no {@code .partial}) holding a summary.json under {@code out}. */
    static Path findLeaf(Path out) throws IOException {
        if (!Files.isDirectory(out)) {
            throw new IOException("garbage output: exited 0 but wrote no run folder");
        }
        List<Path> found = new ArrayList<>();
        try (Stream<Path> s = Files.walk(out, 8)) {
            s.filter(p -> p.getFileName().toString().equals("summary.json"))
                    .filter(p -> !p.getParent().getFileName().toString().endsWith(".partial"))
                    .forEach(p -> found.add(p.getParent()));
        }
        if (found.isEmpty()) {
            throw new IOException("garbage output: exited 0 but left no complete run folder with a summary.json");
        }
        if (found.size() > 1) {
            throw new IOException("garbage output: " + found.size() + " run folders where one was expected");
        }
        return found.get(0);
    }

    /**
     * How long a run ended by SIGHUP, SIGINT or SIGTERM waits for the runner's own stop to show: a
     * signal sent to every process (a system shutdown's SIGTERM) may end the run before the runner's
     * JVM has started its shutdown hook, which then sets {@code stopping} within milliseconds.
     */
    static final long STOP_GRACE_MS = 2000;

    /**
     * Why a run that ended with {@code code} was interrupted rather than failed, or null: only when
     * the runner is stopping (its hook killed the child, or the signal that ended the child reached
     * the runner too). Each run leads its own session, so a terminal's Ctrl-C reaches the runner
     * alone; a runtime that ends itself by one of these signals has failed like any crash.
     */
    static String interruption(int code) {
        return interruption(code, () -> stopping, STOP_GRACE_MS);
    }

    /** {@link #interruption(int)} with the runner's stopping flag and the grace given. */
    static String interruption(int code, java.util.function.BooleanSupplier stopping, long graceMs) {
        if (stopping.getAsBoolean()) {
            return "the runner was stopped";
        }
        if (stopSignal(code) == null) {
            return null;
        }
        long end = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(graceMs);
        while (System.nanoTime() - end < 0) {
            try {
                Thread.sleep(20);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                break;
            }
            if (stopping.getAsBoolean()) {
                return "the runner was stopped (" + stopSignal(code) + ")";
            }
        }
        return stopping.getAsBoolean() ? "the runner was stopped (" + stopSignal(code) + ")" : null;
    }

    /** The stop signal (what a user or the system stops processes with) that exit code {@code code} is a death by, or null. */
    private static String stopSignal(int code) {
        return switch (code) {
            case 128 + 1 -> "SIGHUP";
            case 128 + 2 -> "SIGINT";
            case 128 + 15 -> "SIGTERM";
            default -> null;
        };
    }

    /**
     * What follows "unsupported: " in the workload's last "jmclbench: unsupported: ..." line
     * ("--particles 65536: the HVM holds at most ..."), or null: exit 3 without that line is the
     * runtime's own (a JVM under -XX:+ExitOnOutOfMemoryError exits 3), a failure, not a limit.
     */
    static String unsupportedReason(String tail) {
        String prefix = "jmclbench: unsupported: ";
        List<String> said = tail.lines().map(String::strip).filter(l -> l.startsWith(prefix)).toList();
        return said.isEmpty() ? null : ProcessRunner.lastLine(said.get(said.size() - 1)).substring(prefix.length());
    }

    static String describeExit(int code, String tail) {
        String why = "exit code " + code;
        if (tail.contains("OutOfMemoryError")) {
            return why + ": out of memory (OutOfMemoryError)";
        }
        if (code > 128 && code < 160) {
            int sig = code - 128;
            String name = switch (sig) {
                case 1, 2, 15 -> stopSignal(code);
                case 6 -> "SIGABRT (JVM crash?)";
                case 9 -> "SIGKILL (out of memory killer?)";
                case 11 -> "SIGSEGV (crash)";
                default -> "signal " + sig;
            };
            return why + ": killed by " + name;
        }
        if (code == 2) {
            return why + ": the workload rejected its input: " + ProcessRunner.lastLine(tail);
        }
        return why + (tail.isBlank() ? "" : ": " + ProcessRunner.lastLine(tail));
    }

    /**
     * The last lines of a file (the end of a stack trace says most), read from its last
     * {@link #TAIL_READ_BYTES} only: a runtime that floods its stderr with gigabytes must not take
     * the runner's memory with it.
     */
    static String tail(Path file) {
        try (java.nio.channels.FileChannel ch = java.nio.channels.FileChannel.open(file)) {
            long size = ch.size();
            long from = Math.max(0, size - TAIL_READ_BYTES);
            // to the end seen above: the file may still grow (an orphan writing on)
            String text = org.jmclbench.tooling.runtime.ProcessRunner.readSpan(ch, from, (int) (size - from));
            List<String> lines = text.lines().toList();
            if (from > 0 && lines.size() > 1) {
                lines = lines.subList(1, lines.size()); // the first line read is cut
            }
            String t = String.join("\n", lines.subList(Math.max(0, lines.size() - STDERR_TAIL_LINES), lines.size()));
            return t.length() > STDERR_TAIL_CHARS ? t.substring(t.length() - STDERR_TAIL_CHARS) : t;
        } catch (IOException e) {
            return "";
        }
    }

    private static String firstLine(String s) {
        if (s == null) {
            return "";
        }
        int nl = s.indexOf('\n');
        return nl < 0 ? s : s.substring(0, nl);
    }
}
