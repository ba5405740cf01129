package org.jmclbench.tooling.runtime;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.util.List;

import org.junit.jupiter.api.Test;

class CpuListTest {
    @Test
    void rangesAndSinglesInOrder() {
        assertEquals(List.of(0, 1, 2, 5), CpuList.parse("0-2,5"));
        assertEquals(List.of(), CpuList.parse(" "));
    }

    @Test
    void aMalformedListIsAnIllegalArgumentNeverAnotherException() {
        // "-" was an ArrayIndexOutOfBoundsException (found by bench/fuzz.sh's java-matrix target)
        for (String bad : List.of("-", "1-", "-3", "3-1", "1-2-3", "x", "1,,-")) {
            assertThrows(IllegalArgumentException.class, () -> CpuList.parse(bad), bad);
        }
    }
}
