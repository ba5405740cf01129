package org.jmclbench.verification.jpf;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.lang.reflect.Field;

import org.junit.jupiter.api.Test;

/** The fields left out of JPF's state matching are named by string: each must still exist, as a long. */
class IgnoreClockReadingsTest {
    @Test
    void everyIgnoredFieldExistsAndHoldsAClockReading() throws Exception {
        for (String full : IgnoreClockReadings.FIELDS) {
            int dot = full.lastIndexOf('.');
            Field f = Class.forName(full.substring(0, dot)).getDeclaredField(full.substring(dot + 1));
            assertEquals(long.class, f.getType(), full);
        }
    }
}
