package org.jmclbench.workload.testing;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;

import org.jmclbench.workload.WorkloadMain;

/** The workload's main called in the test's JVM, keeping what the last call printed. */
public final class WorkloadCall {
    private final ByteArrayOutputStream out = new ByteArrayOutputStream();
    private final ByteArrayOutputStream err = new ByteArrayOutputStream();

    /** Runs the workload with {@code args}, forgetting the previous call's output; its exit code. */
    public int run(String... args) {
        out.reset();
        err.reset();
        return WorkloadMain.run(args, new PrintStream(out), new PrintStream(err));
    }

    /** What the last call printed on stdout. */
    public String out() {
        return new String(out.toByteArray(), StandardCharsets.UTF_8);
    }

    /** What the last call printed on stderr. */
    public String err() {
        return new String(err.toByteArray(), StandardCharsets.UTF_8);
    }
}
