package org.jmclbench.tooling.runner;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.List;

import com.fasterxml.jackson.databind.ObjectMapper;
import org.jmclbench.tooling.store.StoredRuns;
import org.junit.jupiter.api.Test;

/** The RTSJ program's two designs are two engines of the matrix, passed to the workload as its engine and design. */
class RtsjEnginesTest {

    @Test
    void eachDesignIsItsOwnEngineWithItsOwnArgumentsAndRuntimeName() {
        assertEquals(List.of("--engine", "rtsj", "--rtsj-design", "thesis"), Engines.workloadArgs(Engines.RTSJ));
        assertEquals(List.of("--engine", "rtsj", "--rtsj-design", "atomic"), Engines.workloadArgs(Engines.RTSJ_ATOMIC));
        assertEquals(List.of("--engine", "scj"), Engines.workloadArgs(Engines.SCJ));
        assertEquals(List.of(), Engines.workloadArgs(Engines.JAVASE));
        assertEquals("-rtsj-thesis", Engines.runtimeSuffix(Engines.RTSJ));
        assertEquals("-rtsj-atomic", Engines.runtimeSuffix(Engines.RTSJ_ATOMIC));
        assertEquals("-scj", Engines.runtimeSuffix(Engines.SCJ));
        assertEquals("", Engines.runtimeSuffix(Engines.JAVASE));
        assertEquals(List.of("preallocated", "allocating"), Engines.memoryStyles(Engines.RTSJ_ATOMIC));
    }

    @Test
    void aStoredRunsEngineIncludesTheDesign() throws Exception {
        ObjectMapper json = new ObjectMapper();
        assertEquals("rtsj-atomic", StoredRuns.engineOf(json.readTree("{\"engine\":\"rtsj\",\"rtsjDesign\":\"atomic\"}"), "javase"));
        assertEquals("rtsj", StoredRuns.engineOf(json.readTree("{\"engine\":\"rtsj\",\"rtsjDesign\":\"thesis\"}"), "javase"));
        assertEquals("scj", StoredRuns.engineOf(json.readTree("{\"engine\":\"scj\"}"), "javase"));
        assertEquals("javase", StoredRuns.engineOf(json.readTree("{}"), "javase"));
    }
}
