package org.jmclbench.rtsjcompat;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTimeoutPreemptively;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.File;
import java.net.URL;
import java.net.URLClassLoader;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import javax.safetycritical.Safelet;
import javax.tools.JavaCompiler;
import javax.tools.ToolProvider;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

/**
 * The probe program (src/test/scj-probe), which scripts/check-icecap-api.sh also compiles
 * against the icecap SDK, compiles against this library for Java 8 and runs to its end.
 */
class ProbeProgramTest {
    @BeforeEach
    void systemTime() {
        TimeSource.install(new SystemTimeSource());
    }

    @Test
    void compilesForJava8AndRunsToItsEnd() throws Exception {
        Path out = Files.createTempDirectory("scj-probe");
        JavaCompiler javac = ToolProvider.getSystemJavaCompiler();
        int rc = javac.run(null, null, null, "--release", "8", "-d", out.toString(),
                "-cp", new File("target/classes").getAbsolutePath(),
                new File("src/test/scj-probe/probe/ProbeSafelet.java").getAbsolutePath());
        assertEquals(0, rc, "the probe compiles against rtsj-compat");
        try (URLClassLoader loader = new URLClassLoader(new URL[] {out.toUri().toURL()}, getClass().getClassLoader())) {
            Class<?> c = loader.loadClass("probe.ProbeSafelet");
            // First launch pays the JVM's class loading, which the probe's small areas cannot hold.
            RunReport warm = assertTimeoutPreemptively(Duration.ofSeconds(60),
                    () -> ScjRuntime.warmUp((Safelet) c.getDeclaredConstructor().newInstance(), 1));
            assertTrue(warm.succeeded(), () -> String.valueOf(warm.failure()));
            int[] releases = (int[]) c.getField("RELEASES").get(null);
            releases[0] = releases[1] = releases[2] = 0;
            RunReport r = assertTimeoutPreemptively(Duration.ofSeconds(60),
                    () -> ScjRuntime.launch((Safelet) c.getDeclaredConstructor().newInstance(), 1));
            assertTrue(r.succeeded(), () -> String.valueOf(r.failure()));
            assertEquals(3, releases[0]);
            assertTrue(r.area("MissionMemory").peakBytes() <= 50000);
        }
    }
}
