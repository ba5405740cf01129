package org.jmclbench.workload;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.File;

import org.jmclbench.workload.testing.SyntheticDataset;
import org.jmclbench.workload.testing.WorkloadCall;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The workload's command line as a whole: {@code [run] [options]} (docs/FORMATS.md section 2), as the C baseline takes it. */
class WorkloadMainTest {
    @TempDir
    File tmp;

    private final WorkloadCall call = new WorkloadCall();

    @Test
    void theThesisCommandLineNeedsNoRunWord() throws Exception {
        File ds = SyntheticDataset.write(new File(tmp, "ds"), 1.0, 3, true, false);
        File out = new File(tmp, "out");
        assertEquals(0, call.run("-p", "20", "-n", "2", "-j", "local", "-O", out.getPath(), "--ideal",
                "-odo", new File(ds, "odometry.txt").getPath(), "-laser", new File(ds, "laser.txt").getPath(),
                "-real", new File(ds, "real.txt").getPath()), call.err());
        File dir = new File(out, "local/nocov/20/IdealTest/2");
        assertEquals(dir.getPath(), call.out().trim());
        assertTrue(new File(dir, "summary.json").isFile(), dir + " has no summary.json");

        assertEquals(0, call.run("-h"), call.err());
        assertTrue(call.out().startsWith("usage: "), call.out());
        assertEquals(2, call.run("foo"));
        assertEquals("jmclbench: foo: unexpected argument (see --help)\n", call.err().replace("\r\n", "\n"));
        assertEquals(2, call.run("run", "run"));
        assertEquals("jmclbench: run: unexpected argument (see --help)\n", call.err().replace("\r\n", "\n"));
    }
}
