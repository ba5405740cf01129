package org.jmclbench.workload.data;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.io.IOException;
import java.util.Arrays;

import com.code_intelligence.jazzer.junit.FuzzTest;

/**
 * Jazzer targets of the dataset readers, each differential: the Java reader and the C reader
 * (native/tests/dataset_dump.c, one process for the run) must say the same of every input,
 * or the input is a finding. A normal test run replays the kept inputs
 * ({@code DatasetFuzzTestInputs/}); JAZZER_FUZZ=1 or bench/fuzz.sh fuzzes.
 */
class DatasetFuzzTest {
    private static NativeReader c;

    private static synchronized NativeReader c() throws IOException {
        if (c == null) {
            c = NativeReader.start();
        }
        return c;
    }

    /** The first byte picks odometry or real (4 columns) or laser (2); the rest is the file. */
    @FuzzTest(maxDuration = "10m")
    void eventFiles(byte[] data) throws IOException {
        if (data.length == 0) {
            return;
        }
        int columns = (data[0] & 1) == 0 ? 4 : 2;
        byte[] file = Arrays.copyOfRange(data, 1, data.length);
        assertEquals(c().series(file, columns), DatasetDump.series(file, columns));
    }

    /** A dataset.properties. */
    @FuzzTest(maxDuration = "10m")
    void properties(byte[] data) throws IOException {
        assertEquals(c().properties(data), DatasetDump.properties(data));
    }
}
