package org.jmclbench.workload.rtsj;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.File;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;

import org.jmclbench.workload.RunOptions;
import org.jmclbench.workload.testing.SyntheticDataset;
import org.jmclbench.workload.testing.WorkloadCall;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** {@code --engine rtsj}: its run folder, its facts in summary.json, and its bad input. */
class RtsjEngineTest {
    @TempDir
    File tmp;

    private final WorkloadCall call = new WorkloadCall();

    @Test
    void eachDesignWritesItsOwnRunFolderAndEveryEventEnds() throws Exception {
        File ds = SyntheticDataset.write(new File(tmp, "ds"), 2.0, 3, true, true);
        File o = new File(tmp, "out");
        for (String design : new String[] {"thesis", "atomic"}) {
            for (String policy : new String[] {"queue", "terminate"}) {
                assertEquals(0, call.run("run", "--engine", "rtsj", "--rtsj-design", design, "--policy", policy, "-p",
                        "100", "--time-scale", "0.5", "--dataset", ds.getPath(), "-O", o.getPath()), call.err());
                File dir = new File(call.out().trim());
                String runtime = RunOptions.defaultRuntimeName() + "-rtsj-" + design;
                assertTrue(dir.getPath().startsWith(new File(o, runtime).getPath()), dir.getPath());
                String s = new String(Files.readAllBytes(new File(dir, "summary.json").toPath()), StandardCharsets.UTF_8);
                assertTrue(s.contains("\"kind\": \"rtsj\""), s);
                assertTrue(s.contains("\"design\": \"" + design + "\""), s);
                assertTrue(s.contains("\"abortLatencyNs\""), s);
                assertFalse(s.contains("pending"), s);
                if (policy.equals("queue")) {
                    assertTrue(s.contains("\"skipped\": 0") && s.contains("\"terminated\": 0"), s);
                }
            }
        }
    }

    @Test
    void optionsOfTheDesignAreBadUsageElsewhere() {
        assertEquals(2, call.run("run", "--rtsj-design", "atomic"));
        assertTrue(call.err().startsWith("jmclbench: --rtsj-design: chooses the rtsj engine's design"), call.err());
        assertEquals(2, call.run("run", "--engine", "rtsj", "--rtsj-design", "fast"));
        assertTrue(call.err().startsWith("jmclbench: --rtsj-design: 'fast' is not one of thesis|atomic"), call.err());
        assertEquals(2, call.run("run", "--engine", "rtsj", "--memory", "scoped"));
        assertTrue(call.err().startsWith("jmclbench: --memory: 'scoped' is not a memory style of the rtsj engine"), call.err());
        assertEquals(1, call.err().trim().split("\n").length, call.err());
    }
}
