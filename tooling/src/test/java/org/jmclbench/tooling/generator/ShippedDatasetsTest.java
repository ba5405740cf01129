package org.jmclbench.tooling.generator;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.regex.Pattern;

import org.jmclbench.tooling.Fixtures;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/** The datasets in {@code data/} are exactly what the generator writes today (data/README.md). */
class ShippedDatasetsTest {
    private static final Pattern NUMBER = Pattern.compile("-?[0-9]\\.[0-9]{16}e[+-][0-9]{2,3}");

    @ParameterizedTest
    @ValueSource(strings = {"match", "match-short", "match-quick", "stay", "figure8", "kidnap"})
    void regeneratingGivesTheSameBytes(String name, @TempDir Path tmp) throws Exception {
        Path shipped = Fixtures.projectHome().resolve("data").resolve(name);
        Scenario s = Scenario.byName(name);
        SimulatedRun run = new Simulator(Playground.thesis(), SensorNoise.DEFAULT)
                .run(s, 1, GenerateCommand.odometryCount(s.defaultDuration()));
        Path out = tmp.resolve(name);
        DatasetWriter.write(run, out, false);
        for (String file : DatasetWriter.FILES) {
            assertArrayEquals(Files.readAllBytes(shipped.resolve(file)), Files.readAllBytes(out.resolve(file)),
                    name + "/" + file + " differs from a fresh generation (see data/README.md)");
        }
        try (var files = Files.list(shipped)) {
            assertEquals(DatasetWriter.FILES.size(), files.count(), name + " holds exactly the dataset files");
        }
    }

    @ParameterizedTest
    @ValueSource(strings = {"match", "match-short", "match-quick", "stay", "figure8", "kidnap"})
    void filesFollowTheFormat(String name) throws IOException {
        Path dir = Fixtures.projectHome().resolve("data").resolve(name);
        checkTable(dir.resolve("odometry.txt"), 4);
        checkTable(dir.resolve("laser.txt"), 2);
        checkTable(dir.resolve("real.txt"), 4);
        List<String> odometry = Files.readAllLines(dir.resolve("odometry.txt"));
        List<String> real = Files.readAllLines(dir.resolve("real.txt"));
        assertEquals(odometry.size(), real.size());
        for (int i = 0; i < odometry.size(); i++) {
            assertEquals(odometry.get(i).split(" {2}")[0], real.get(i).split(" {2}")[0], "same times");
        }
        String props = Files.readString(dir.resolve("dataset.properties"));
        assertTrue(props.contains("\nscenario=" + name + "\n"));
        assertTrue(props.contains("\nformat=jmclbench-dataset/1\n"));
    }

    private static void checkTable(Path file, int columns) throws IOException {
        byte[] bytes = Files.readAllBytes(file);
        assertTrue(bytes.length > 0 && bytes[bytes.length - 1] == '\n', file + " ends with a line end");
        double previous = 0;
        int line = 0;
        for (String l : Files.readAllLines(file)) {
            line++;
            String[] tokens = l.split(" {2}", -1);
            assertEquals(columns, tokens.length, file + ":" + line);
            for (String t : tokens) {
                assertTrue(NUMBER.matcher(t).matches(), file + ":" + line + ": " + t);
            }
            double time = Double.parseDouble(tokens[0]);
            assertTrue(time >= previous, file + ":" + line + ": sorted");
            previous = time;
        }
    }
}
