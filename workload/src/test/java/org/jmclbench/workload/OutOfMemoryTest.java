package org.jmclbench.workload;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.File;
import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.util.Arrays;
import java.util.concurrent.TimeUnit;

import org.jmclbench.workload.testing.SyntheticDataset;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Options that need more heap than the JVM has are the run's failure in one line that says what to
 * change (exit 1, only the .partial folder), not a stack trace: the heap is too small, nothing broke.
 */
class OutOfMemoryTest {

    @TempDir
    File tmp;

    @Test
    void tooManyParticlesForTheHeapIsOneLineNamingTheHeap() throws Exception {
        File data = SyntheticDataset.write(new File(tmp, "data"), 1.0, 1, true, false);
        String java = System.getProperty("java.home") + File.separator + "bin" + File.separator + "java";
        // 20 million particles want hundreds of MiB of particle arrays: far past a 32 MiB heap
        Process p = new ProcessBuilder(Arrays.asList(java, "-Xmx32m", "-cp", System.getProperty("java.class.path"),
                WorkloadMain.class.getName(), "run", "-p", "20000000", "--dataset", data.getPath(),
                "-O", new File(tmp, "out").getPath(), "--time-scale", "0.1")).redirectOutput(new File(tmp, "stdout")).start();
        String err = read(p.getErrorStream());
        assertTrue(p.waitFor(120, TimeUnit.SECONDS), "the run ended");
        assertEquals(WorkloadMain.FAILURE, p.exitValue(), err);
        assertEquals(1, err.trim().split("\n").length, err);
        assertTrue(err.matches("jmclbench: failure: out of memory \\(Java heap space\\): this JVM's heap is at most \\d+ MiB"
                + " \\(set it with -Xmx; fewer particles need less\\)\\s*"), err);
        assertFalse(new File(tmp, "out").exists() && containsSummary(new File(tmp, "out")), "nothing recorded as valid");
    }

    private static boolean containsSummary(File dir) {
        File[] children = dir.listFiles();
        if (children == null) {
            return dir.getName().equals("summary.json");
        }
        for (File c : children) {
            if (containsSummary(c)) {
                return true;
            }
        }
        return false;
    }

    private static String read(InputStream in) throws IOException {
        java.io.ByteArrayOutputStream b = new java.io.ByteArrayOutputStream();
        byte[] buf = new byte[4096];
        for (int n; (n = in.read(buf)) > 0;) {
            b.write(buf, 0, n);
        }
        return new String(b.toByteArray(), StandardCharsets.UTF_8);
    }
}
