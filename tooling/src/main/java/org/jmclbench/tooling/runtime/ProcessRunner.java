package org.jmclbench.tooling.runtime;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.function.Consumer;

/** Runs a short helper process (a probe) from an argument list, with a timeout, capturing its output. */
public final class ProcessRunner {

    /** What a finished (or killed) helper process left: exit code, output, whether it timed out. */
    public record Result(int exitCode, String stdout, String stderr, boolean timedOut) {
        /** Standard output and error together, for parsers that accept either. */
        public String output() {
            return stdout + stderr;
        }

        public boolean ok() {
            return !timedOut && exitCode == 0;
        }
    }

    private ProcessRunner() {
    }

    /**
     * Runs {@code command} with a timeout; output goes to temporary files (not pipes) so that a
     * chatty child can never block on a full pipe. A start failure is reported as exit code 127.
     */
    public static Result run(List<String> command, long timeoutMs) {
        return run(command, timeoutMs, p -> { });
    }

    /**
     * {@link #run(List, long)}, handing the process to {@code started} as soon as it runs (for a
     * caller's shutdown hook to kill it, should the caller be stopped while it waits).
     */
    public static Result run(List<String> command, long timeoutMs, Consumer<Process> started) {
        Path out = null;
        Path err = null;
        try {
            out = Files.createTempFile("jmclbench-probe", ".out");
            err = Files.createTempFile("jmclbench-probe", ".err");
            ProcessBuilder pb = new ProcessBuilder(command);
            pb.redirectInput(ProcessBuilder.Redirect.from(new java.io.File("/dev/null")));
            pb.redirectOutput(out.toFile());
            pb.redirectError(err.toFile());
            Process p;
            try {
                p = pb.start();
            } catch (IOException e) {
                return new Result(127, "", e.getMessage() == null ? "cannot start" : e.getMessage(), false);
            }
            started.accept(p);
            boolean finished = p.waitFor(timeoutMs, TimeUnit.MILLISECONDS);
            if (!finished) {
                ProcessTree.kill(p);
            }
            int code = finished ? p.exitValue() : -1;
            return new Result(code, readEnds(out), readEnds(err), !finished);
        } catch (IOException e) {
            return new Result(127, "", String.valueOf(e.getMessage()), false);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return new Result(130, "", "interrupted", false);
        } finally {
            deleteQuietly(out);
            deleteQuietly(err);
        }
    }

    /**
     * A whole file as UTF-8, malformed bytes replaced (a crashing child may print anything), read
     * through a stream because procfs files report size 0 and {@code Files.readString} trusts it.
     */
    public static String readText(Path p) throws IOException {
        try (java.io.InputStream in = Files.newInputStream(p)) {
            return new String(in.readAllBytes(), StandardCharsets.UTF_8);
        }
    }

    /** The longest last line {@link #lastLine} gives: a line of a binary flood can be megabytes. */
    static final int MAX_LAST_LINE = 200;

    /**
     * The last line of a child's output that says something, for a one-line failure: blank lines,
     * control characters (a flooded log's NUL padding) and the JVM's "Picked
     * up JAVA_TOOL_OPTIONS" echo are passed over; cut at {@link #MAX_LAST_LINE} characters;
     * "no message" when nothing is left.
     */
    public static String lastLine(String output) {
        String[] lines = output.split("\n");
        for (int i = lines.length - 1; i >= 0; i--) {
            String t = lines[i].replaceAll("\\p{Cntrl}", "").strip();
            if (!t.isEmpty() && !t.startsWith("Picked up ")) {
                return t.length() > MAX_LAST_LINE ? t.substring(0, MAX_LAST_LINE) : t;
            }
        }
        return "no message";
    }

    /** What of a child's output stream is kept: its first and last half of this. */
    static final int MAX_OUTPUT_BYTES = 1024 * 1024;

    /**
     * A child's output, whole up to {@link #MAX_OUTPUT_BYTES}, else its beginning (where a version
     * banner stands) and its end (where a crash says why), with what is left out between them said:
     * a runtime under test that floods its output must not take the caller's memory with it.
     */
    static String readEnds(Path p) throws IOException {
        try (java.nio.channels.FileChannel ch = java.nio.channels.FileChannel.open(p)) {
            long size = ch.size();
            if (size <= MAX_OUTPUT_BYTES) {
                return readText(p);
            }
            int half = MAX_OUTPUT_BYTES / 2;
            return readSpan(ch, 0, half) + "\n[... " + (size - 2L * half) + " bytes left out ...]\n"
                    + readSpan(ch, size - half, half);
        }
    }

    /**
     * Up to {@code n} bytes of {@code ch} from {@code from} as UTF-8, malformed bytes replaced: fewer
     * where the file ends first (a file still growing is read to the length asked, no further).
     */
    public static String readSpan(java.nio.channels.FileChannel ch, long from, int n) throws IOException {
        java.nio.ByteBuffer buf = java.nio.ByteBuffer.allocate(n);
        while (buf.hasRemaining() && ch.read(buf, from + buf.position()) > 0) {
            // read on: a channel may return fewer bytes than asked
        }
        return new String(buf.array(), 0, buf.position(), StandardCharsets.UTF_8);
    }

    private static void deleteQuietly(Path p) {
        if (p != null) {
            try {
                Files.deleteIfExists(p);
            } catch (IOException ignored) {
                // a temporary file left behind is harmless
            }
        }
    }
}
