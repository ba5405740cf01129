package org.jmclbench.tooling.runner;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;

import com.code_intelligence.jazzer.junit.FuzzTest;
import org.jmclbench.tooling.cli.BadUsageException;

/**
 * Jazzer target of the matrix file parser: a file either sets a matrix or is refused with a
 * one-line BadUsageException naming the file and line (or the file as a whole); any other
 * exception is a finding. The input is written to one scratch file per run.
 */
class MatrixFileFuzzTest {
    private static Path file;

    private static synchronized Path file() {
        if (file == null) {
            try {
                file = Files.createTempFile("matrix-fuzz", ".matrix");
            } catch (IOException e) {
                throw new UncheckedIOException(e);
            }
            file.toFile().deleteOnExit();
        }
        return file;
    }

    @FuzzTest(maxDuration = "10m")
    void matrixFile(byte[] data) throws IOException {
        Path f = file();
        Files.write(f, data);
        try {
            MatrixFile.read(f, new MatrixSpec());
        } catch (BadUsageException e) {
            String m = e.getMessage();
            assertTrue(m.indexOf('\n') < 0 && m.indexOf('\r') < 0, "one line: " + m);
            assertTrue(m.startsWith(f + ":") || m.startsWith("--matrix: " + f + ":"), "names the file: " + m);
        }
    }
}
