package org.jmclbench.workload.load;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.File;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;

import org.jmclbench.workload.BadInputException;
import org.jmclbench.workload.RunOptions;
import org.jmclbench.workload.RunOptionsParser;
import org.jmclbench.workload.testing.SyntheticDataset;
import org.jmclbench.workload.testing.WorkloadCall;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class AllocationNoiseTest {
    @TempDir
    File tmp;

    @Test
    void allocatesInTheBackgroundUntilStopped() throws Exception {
        AllocationNoise n = AllocationNoise.start(20, 2);
        long deadline = System.nanoTime() + 30_000_000_000L;
        while (n.allocatedBytes() < 1_000_000 && System.nanoTime() < deadline) {
            Thread.sleep(10);
        }
        assertTrue(n.allocatedBytes() >= 1_000_000, "allocated " + n.allocatedBytes());
        n.stop();
        assertFalse(Thread.getAllStackTraces().keySet().stream()
                .anyMatch(t -> t.getName().equals("jmclbench-alloc-noise") && t.isAlive()), "the noise thread ended");
    }

    @Test
    void optionsSwitchItOnAndNameTheScenario() throws Exception {
        RunOptions o = RunOptionsParser.parse(new String[] {"run", "--load-alloc", "200,32"});
        assertEquals(200, o.loadAllocMbPerS);
        assertEquals(32, o.loadAllocLiveMb);
        assertEquals("alloc", o.effectiveLoadName());
        o = RunOptionsParser.parse(new String[] {"--load-alloc=50,0", "--load-name", "mixed"});
        assertEquals("mixed", o.effectiveLoadName());
        assertEquals("none", RunOptionsParser.parse(new String[] {}).effectiveLoadName());
    }

    @Test
    void badOptionsNameTheOption() {
        for (String bad : new String[] {"200", "0,10", "x,1", "10,-1", "1,2,3"}) {
            BadInputException e = assertThrows(BadInputException.class,
                    () -> RunOptionsParser.parse(new String[] {"--load-alloc", bad}));
            assertTrue(e.getMessage().startsWith("--load-alloc: "), e.getMessage());
        }
        assertThrows(BadInputException.class, () -> RunOptionsParser.parse(new String[] {"--load-name", "../x"}));
    }

    /** An ideal run records the load it was asked for, so the load must run beside it (it ran under none). */
    @Test
    void anIdealRunRunsTheLoadItRecords() throws Exception {
        File ds = SyntheticDataset.write(new File(tmp, "ds"), 1.0, 3, true, true);
        WorkloadCall call = new WorkloadCall();
        assertEquals(0, call.run("run", "--ideal", "-p", "50", "--load-alloc", "20,1", "--dataset", ds.getPath(), "-O",
                new File(tmp, "out").getPath()), call.err());
        String s = new String(Files.readAllBytes(new File(call.out().trim(), "summary.json").toPath()),
                StandardCharsets.UTF_8);
        String compact = s.replaceAll("\\s+", "");
        assertTrue(compact.contains("\"load\":{\"scenario\":\"alloc\""), s);
        assertTrue(compact.contains("\"loadAlloc\":{\"allocMbPerS\":20,\"allocLiveMb\":1,\"allocatedBytes\":"), s);
    }
}
