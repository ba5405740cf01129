package org.jmclbench.workload.conformance;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.File;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.TimeUnit;
import java.util.stream.Stream;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The committed vectors are exactly what the Python reference writes: neither was edited alone. */
class VectorFilesTest {
    private static final String[] FILES = {
        "rng.txt", "uniform.txt", "gaussian.txt", "wrap.txt", "bearing.txt", "likelihood.txt", "resample.txt", "mcl.txt",
        "deadlines.txt",
    };

    @Test
    void committedVectorsEqualAFreshRunOfTheReference(@TempDir Path tmp) throws Exception {
        Assumptions.assumeTrue(python3Available(), "python3 is not installed (scripts/install-deps.sh installs it)");
        Path script = VectorFile.folder().resolve("make_vectors.py");
        Process p = new ProcessBuilder("python3", script.toString(), "--out", tmp.toString())
                .redirectErrorStream(true).redirectOutput(tmp.resolve("log").toFile()).start();
        assertTrue(p.waitFor(120, TimeUnit.SECONDS), "make_vectors.py did not finish in 120 s");
        assertEquals(0, p.exitValue(), () -> "make_vectors.py failed: " + read(tmp.resolve("log")));
        for (String name : FILES) {
            byte[] committed = Files.readAllBytes(VectorFile.folder().resolve(name));
            byte[] fresh = Files.readAllBytes(tmp.resolve(name));
            assertArrayEquals(fresh, committed, "conformance/" + name
                    + " differs from what make_vectors.py writes now: rerun it and commit both");
        }
        // Every file the script writes is one of those checked above.
        try (Stream<Path> s = Files.list(tmp)) {
            assertEquals(FILES.length, s.filter(f -> f.toString().endsWith(".txt")).count());
        }
    }

    private static boolean python3Available() {
        for (String dir : System.getenv().getOrDefault("PATH", "").split(File.pathSeparator)) {
            if (Files.isExecutable(new File(dir, "python3").toPath())) {
                return true;
            }
        }
        return false;
    }

    private static String read(Path p) {
        try {
            return new String(Files.readAllBytes(p), java.nio.charset.StandardCharsets.UTF_8);
        } catch (IOException e) {
            return e.toString();
        }
    }
}
