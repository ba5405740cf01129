package org.jmclbench.workload.testing;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.File;
import java.io.IOException;
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

    /**
     * Runs {@code engine} on a dataset written under {@code tmp} whose 11th odometry event comes 10 ms
     * late (its interval 60 ms, the next 40 ms) and checks that this is bad input naming the file
     * and line; returns the dataset's folder. The run was given {@code tmp/out} as its output.
     */
    public File assertRejectsAperiodicOdometry(File tmp, String engine) throws IOException {
        File ds = SyntheticDataset.write(new File(tmp, "ds"), 2.0, 3, true, false);
        int line = SyntheticDataset.delayOdometryEvent(ds, 10, 0.010);
        assertEquals(2, run("run", "--engine", engine, "--dataset", ds.getPath(), "-O", new File(tmp, "out").getPath()),
                err());
        String odo = new File(ds, "odometry.txt").getPath();
        assertTrue(err().startsWith("jmclbench: " + odo + ":" + line + ": odometry is not periodic"), err());
        return ds;
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
