package org.jmclbench.workload.load;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.jmclbench.workload.BadInputException;
import org.jmclbench.workload.RunOptions;
import org.jmclbench.workload.RunOptionsParser;
import org.junit.jupiter.api.Test;

class AllocationNoiseTest {

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
}
