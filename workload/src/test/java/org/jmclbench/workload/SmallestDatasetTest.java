package org.jmclbench.workload;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.File;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.util.List;
import java.util.concurrent.TimeUnit;

import org.jmclbench.workload.testing.WorkloadCall;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/**
 * The smallest dataset a reader accepts, one odometry and one laser line, runs on every engine
 * under every policy: each of its two events ends once, as in any other run.
 */
@Timeout(value = 120, unit = TimeUnit.SECONDS)
class SmallestDatasetTest {
    @TempDir
    File tmp;

    private final WorkloadCall call = new WorkloadCall();

    @Test
    void twoEventsRunOnEveryEngineUnderEveryPolicy() throws IOException {
        File ds = new File(tmp, "two");
        ds.mkdirs();
        write(new File(ds, "odometry.txt"), "5.0000000000000000e-02  1.0e-03  0.0e+00  0.0e+00\n");
        write(new File(ds, "laser.txt"), "9.0000000000000000e-02  6.1056343391140710e+00\n");
        write(new File(ds, "real.txt"), "5.0000000000000000e-02  4.0e-01  4.0e-01  0.0e+00\n");
        String[][] engines = {{"--engine", "javase"}, {"--engine", "scj"}, {"--engine", "rtsj", "--rtsj-design", "thesis"},
            {"--engine", "rtsj", "--rtsj-design", "atomic"}};
        for (String[] engine : engines) {
            for (String policy : new String[] {"skip", "terminate", "queue"}) {
                String what = String.join(" ", engine) + " --policy " + policy;
                String[] args = concat(new String[] {"run", "-p", "10", "--policy", policy, "--dataset", ds.getPath(),
                    "-O", new File(tmp, "out").getPath()}, engine);
                assertEquals(0, call.run(args), what + ": " + call.err());
                File dir = new File(call.out().trim());
                for (String jobs : new String[] {"odoData.txt", "laserData.txt"}) {
                    List<String> lines = Files.readAllLines(new File(dir, jobs).toPath(), StandardCharsets.UTF_8);
                    assertEquals(2, lines.size(), what + ": " + lines);
                    assertTrue(lines.get(1).split(" ")[5].matches("done|late|skipped|terminated"), what + ": " + lines);
                }
            }
        }
    }

    private static String[] concat(String[] a, String[] b) {
        String[] r = new String[a.length + b.length];
        System.arraycopy(a, 0, r, 0, a.length);
        System.arraycopy(b, 0, r, a.length, b.length);
        return r;
    }

    private static void write(File f, String text) throws IOException {
        Files.write(f.toPath(), text.getBytes(StandardCharsets.UTF_8));
    }
}
