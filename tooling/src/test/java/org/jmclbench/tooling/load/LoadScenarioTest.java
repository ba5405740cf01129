package org.jmclbench.tooling.load;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;

import org.jmclbench.tooling.cli.BadUsageException;
import org.junit.jupiter.api.Test;

class LoadScenarioTest {

    @Test
    void parsesTheDimension() throws Exception {
        assertEquals(List.of(LoadScenario.NONE, LoadScenario.CPU, LoadScenario.ALLOC, LoadScenario.MIXED),
                LoadScenario.parseList("--load", "none,cpu,alloc,mixed"));
        assertTrue(LoadScenario.MIXED.cpu() && LoadScenario.MIXED.alloc());
        assertTrue(!LoadScenario.CPU.alloc() && !LoadScenario.ALLOC.cpu() && !LoadScenario.NONE.cpu());
    }

    @Test
    void badNamesNameTheOption() {
        BadUsageException e = assertThrows(BadUsageException.class, () -> LoadScenario.parseList("--load", "none,gpu"));
        assertEquals("--load: 'gpu' is not one of none, cpu, alloc, mixed", e.getMessage());
        assertThrows(BadUsageException.class, () -> LoadScenario.parseList("--load", "cpu,cpu"));
        assertThrows(BadUsageException.class, () -> LoadScenario.parseList("--load", ""));
    }
}
