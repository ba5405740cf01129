package org.jmclbench.workload.release;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.File;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.stream.Collectors;

import org.jmclbench.workload.testing.SyntheticDataset;
import org.jmclbench.workload.testing.WorkloadCall;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/** The abort rehearsal before a terminate run, whatever the dataset's size. */
@Timeout(value = 60, unit = TimeUnit.SECONDS)
class AbortRehearsalTest {
    @TempDir
    File tmp;

    private final WorkloadCall call = new WorkloadCall();

    /**
     * The rehearsal replays three events of its own; on a dataset of two (one odometry, one laser
     * line) it wrote into the run's records, two long, and the run crashed before its first event.
     */
    @Test
    void aTerminateRunOfADatasetShorterThanTheRehearsalCompletes() throws Exception {
        File ds = SyntheticDataset.write(new File(tmp, "ds"), 2.0, 3, true, true);
        for (String f : new String[] {"odometry.txt", "laser.txt", "real.txt"}) {
            keepFirstDataLine(ds.toPath().resolve(f));
        }
        File o = new File(tmp, "out");
        for (String[] engine : new String[][] {{"--engine", "javase"}, {"--engine", "rtsj", "--rtsj-design", "thesis"},
            {"--engine", "rtsj", "--rtsj-design", "atomic"}}) {
            String[] args = {"run", "--policy", "terminate", "-p", "50", "--dataset", ds.getPath(), "-O", o.getPath()};
            String[] all = new String[args.length + engine.length];
            System.arraycopy(args, 0, all, 0, args.length);
            System.arraycopy(engine, 0, all, args.length, engine.length);
            assertEquals(0, call.run(all), String.join(" ", engine) + ": " + call.err());
            String s = new String(Files.readAllBytes(new File(call.out().trim(), "summary.json").toPath()),
                    StandardCharsets.UTF_8);
            assertTrue(s.contains("\"status\": \"complete\""), s);
        }
    }

    private static void keepFirstDataLine(Path file) throws IOException {
        List<String> data = Files.readAllLines(file, StandardCharsets.UTF_8).stream()
                .filter(l -> !l.startsWith("#") && !l.trim().isEmpty()).limit(1).collect(Collectors.toList());
        assertEquals(1, data.size(), file + " has no data line");
        Files.write(file, data, StandardCharsets.UTF_8);
    }
}
