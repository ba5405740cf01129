package org.jmclbench.workload.scj;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.File;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.util.List;

import org.jmclbench.workload.RunOptions;
import org.jmclbench.workload.WorkloadMain;
import org.jmclbench.workload.testing.SyntheticDataset;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The {@code --engine scj} command line: its outputs, its contract with the tooling, and its bad input. */
class ScjEngineTest {
    @TempDir
    File tmp;

    private final ByteArrayOutputStream out = new ByteArrayOutputStream();
    private final ByteArrayOutputStream err = new ByteArrayOutputStream();

    private int main(String... args) {
        out.reset();
        err.reset();
        return WorkloadMain.run(args, new PrintStream(out), new PrintStream(err));
    }

    private String err() {
        return new String(err.toByteArray(), StandardCharsets.UTF_8);
    }

    private static String read(File f) throws IOException {
        return new String(Files.readAllBytes(f.toPath()), StandardCharsets.UTF_8);
    }

    @Test
    void anScjRunWritesTheRunFolderWithEngineAndMemoryAreas() throws Exception {
        File ds = SyntheticDataset.write(new File(tmp, "ds"), 3.0, 3, true, true);
        File o = new File(tmp, "out");
        for (String memory : new String[] {"preallocated", "scoped"}) {
            assertEquals(0, main("run", "--engine", "scj", "--memory", memory, "-p", "200", "--policy", "queue",
                    "--time-scale", "0.5", "--dataset", ds.getPath(), "-O", o.getPath(), "-n", memory.length() + ""),
                    err());
            File dir = new File(out.toString().trim());
            String runtime = RunOptions.defaultRuntimeName() + "-scj";
            assertEquals(new File(o, runtime + "/nocov/200/QueueTest/" + memory.length()).getPath(), dir.getPath());
            for (String f : new String[] {"odoData.txt", "laserData.txt", "position.txt", "positionDeviation.txt",
                    "data.txt", "summary.json"}) {
                assertTrue(new File(dir, f).isFile(), f);
            }
            String s = read(new File(dir, "summary.json"));
            assertTrue(s.contains("\"engine\": \"scj\""), s);
            assertTrue(s.contains("\"kind\": \"scj\""), s);
            assertTrue(s.contains("\"memory\": \"" + memory + "\""), s);
            for (String area : new String[] {"immortal", "mission", "predict", "update", "sensor"}) {
                assertTrue(s.contains("\"name\": \"" + area + "\""), area + " in " + s);
            }
            List<String> odo = Files.readAllLines(new File(dir, "odoData.txt").toPath());
            assertEquals(60 + 1, odo.size(), "a line per odometry event and the header");
            assertFalse(odo.get(1).contains("pending"));
        }
    }

    @Test
    void everyRunSaysItsEngineIdealOnesToo() throws Exception {
        File ds = SyntheticDataset.write(new File(tmp, "ds"), 2.0, 3, true, true);
        File o = new File(tmp, "out");
        assertEquals(0, main("run", "--ideal", "-p", "50", "--dataset", ds.getPath(), "-O", o.getPath()), err());
        String s = read(new File(new File(out.toString().trim()), "summary.json"));
        assertTrue(s.contains("\"engine\": \"javase\""), s);
        assertTrue(s.contains("\"kind\": \"javase\""), s);
        assertTrue(s.contains("\"name\": \"heap\""), s);
        assertEquals(0, main("run", "--ideal", "--engine", "scj", "-p", "50", "--dataset", ds.getPath(), "-O",
                o.getPath()), err());
        String scj = read(new File(new File(out.toString().trim()), "summary.json"));
        assertTrue(scj.contains("\"kind\": \"scj\""), scj);
    }

    @Test
    void anUnknownEngineOrAMemoryStyleTheEngineLacksIsBadUsage() {
        assertEquals(2, main("run", "--engine", "jamaica"));
        assertTrue(err().startsWith("jmclbench: --engine: 'jamaica'"), err());
        assertEquals(1, err().trim().split("\n").length, err());
        assertEquals(2, main("run", "--engine", "scj", "--memory", "allocating"));
        assertTrue(err().startsWith("jmclbench: --memory:"), err());
        assertEquals(2, main("run", "--memory", "scoped"));
        assertTrue(err().startsWith("jmclbench: --memory:"), err());
        assertEquals(2, main("run", "--area-size", "mission=100000"));
        assertTrue(err().startsWith("jmclbench: --area-size:"), err());
        assertEquals(2, main("run", "--engine", "scj", "--area-size", "heap=100000"));
        assertTrue(err().contains("'heap' is not an area"), err());
        assertEquals(2, main("run", "--engine", "scj", "--area-size", "mission"));
    }

    @Test
    void odometryWithoutAPeriodIsBadInputNamingFileAndLine() throws Exception {
        File ds = SyntheticDataset.write(new File(tmp, "ds"), 2.0, 3, true, false);
        File odo = new File(ds, "odometry.txt");
        List<String> lines = Files.readAllLines(odo.toPath(), StandardCharsets.UTF_8);
        // Move the 11th event 10 ms later: its interval is 60 ms, the next 40 ms.
        int row = 10;
        int line = 0;
        int rows = -1;
        for (int i = 0; i < lines.size(); i++) {
            if (!lines.get(i).startsWith("#") && ++rows == row) {
                String[] t = lines.get(i).trim().split("\\s+");
                t[0] = String.format(java.util.Locale.ROOT, "%.16e", Double.parseDouble(t[0]) + 0.010);
                lines.set(i, String.join(" ", t));
                line = i + 1;
            }
        }
        Files.write(odo.toPath(), lines, StandardCharsets.UTF_8);
        File o = new File(tmp, "out");
        assertEquals(2, main("run", "--engine", "scj", "--dataset", ds.getPath(), "-O", o.getPath()), err());
        assertTrue(err().startsWith("jmclbench: " + odo.getPath() + ":" + line + ": odometry is not periodic"), err());
        assertFalse(o.exists() && o.list().length > 0, "nothing recorded");
    }

    @Test
    void anAreaTooSmallFailsTheRunNamingTheAreaAndLeavesOnlyAPartialFolder() throws Exception {
        File ds = SyntheticDataset.write(new File(tmp, "ds"), 1.0, 3, true, true);
        File o = new File(tmp, "out");
        assertEquals(1, main("run", "--engine", "scj", "-p", "4000", "--dataset", ds.getPath(), "-O", o.getPath(),
                "-j", "t", "--area-size", "mission=70000"), err());
        assertTrue(err().startsWith("jmclbench: failure: memory area 'mission' overflowed"), err());
        assertTrue(err().contains("needed"), err());
        assertEquals(1, err().trim().split("\n").length, err());
        File test = new File(o, "t/nocov/4000/SkipTest");
        assertTrue(new File(test, "1.partial").isDirectory());
        assertFalse(new File(test, "1").exists());
    }
}
