package org.jmclbench.workload.data;

import java.io.BufferedReader;
import java.io.File;
import java.io.IOException;
import java.io.InputStreamReader;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

import org.jmclbench.workload.testing.NativeBuild;

/**
 * The C reader, asked through native/tests/dataset_dump.c: one process kept running for many
 * requests ({@code --serve}), or one run on a folder or three files. Builds the harness with
 * make when it is missing or older than the reader.
 */
final class NativeReader implements AutoCloseable {
    /** The project's root, the workload module's parent. */
    static final File HOME = NativeBuild.HOME;

    private final Process process;
    private final OutputStream requests;
    private final BufferedReader answers;

    private NativeReader() throws IOException {
        process = new ProcessBuilder(harness().getPath(), "--serve").redirectError(ProcessBuilder.Redirect.INHERIT)
                .start();
        requests = process.getOutputStream();
        answers = new BufferedReader(new InputStreamReader(process.getInputStream(), StandardCharsets.ISO_8859_1));
    }

    /** A running harness for {@link #series} and {@link #properties}. */
    static NativeReader start() throws IOException {
        return new NativeReader();
    }

    /** The harness, built (once per JVM) by the native Makefile. */
    static File harness() throws IOException {
        return NativeBuild.target("build/dataset_dump");
    }

    /** What the C reader makes of an event file of {@code columns} columns. */
    String series(byte[] file, int columns) throws IOException {
        return ask("series " + columns + " " + file.length + "\n", file);
    }

    /** What the C reader makes of a dataset.properties. */
    String properties(byte[] file) throws IOException {
        return ask("properties " + file.length + "\n", file);
    }

    private String ask(String head, byte[] body) throws IOException {
        requests.write(head.getBytes(StandardCharsets.US_ASCII));
        requests.write(body);
        requests.flush();
        StringBuilder b = new StringBuilder();
        for (;;) {
            String line = answers.readLine();
            if (line == null) {
                throw new IOException("the C harness stopped (exit " + waitFor() + ") after: " + b);
            }
            b.append(line).append('\n');
            if (line.equals("end")) {
                return b.toString();
            }
        }
    }

    private int waitFor() throws IOException {
        return NativeBuild.waitFor(process);
    }

    /** What the C reader makes of a folder (one path) or the thesis's three files. */
    static String dataset(String... files) throws IOException {
        List<String> cmd = new ArrayList<>();
        cmd.add(harness().getPath());
        cmd.addAll(Arrays.asList(files));
        return run(cmd);
    }

    private static String run(List<String> cmd) throws IOException {
        Process p = new ProcessBuilder(cmd).redirectErrorStream(true).start();
        String text = NativeBuild.readAll(p.getInputStream());
        int code = NativeBuild.waitFor(p);
        if (code != 0) {
            throw new IOException(String.join(" ", cmd) + ": exit " + code + ": " + text);
        }
        return text;
    }

    @Override
    public void close() throws IOException {
        requests.close();
        waitFor();
    }
}
