package org.jmclbench.workload.scj;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.File;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.util.List;

import org.jmclbench.rtsjcompat.AllocationMeter;
import org.jmclbench.workload.RunOptions;
import org.jmclbench.workload.testing.SyntheticDataset;
import org.jmclbench.workload.testing.WorkloadCall;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The {@code --engine scj} command line: its outputs, its contract with the tooling, and its bad input. */
class ScjEngineTest {
    @TempDir
    File tmp;

    private final WorkloadCall call = new WorkloadCall();

    private static String read(File f) throws IOException {
        return new String(Files.readAllBytes(f.toPath()), StandardCharsets.UTF_8);
    }

    @Test
    void anScjRunWritesTheRunFolderWithEngineAndMemoryAreas() throws Exception {
        File ds = SyntheticDataset.write(new File(tmp, "ds"), 3.0, 3, true, true);
        File o = new File(tmp, "out");
        for (String memory : new String[] {"preallocated", "scoped"}) {
            assertEquals(0, call.run("run", "--engine", "scj", "--memory", memory, "-p", "200", "--policy", "queue",
                    "--time-scale", "0.5", "--dataset", ds.getPath(), "-O", o.getPath(), "-n", memory.length() + ""),
                    call.err());
            File dir = new File(call.out().trim());
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
            // each private memory says how many of its releases allocated: a scoped release always does
            java.util.regex.Matcher update = java.util.regex.Pattern.compile(
                    "\"name\": \"update\"[^}]*\"releases\": (\\d+),\\s*\"allocatingReleases\": (\\d+)").matcher(s);
            assertTrue(update.find(), s);
            if (memory.equals("scoped")) {
                assertEquals(update.group(1), update.group(2), "every scoped release allocates");
            }
            List<String> odo = Files.readAllLines(new File(dir, "odoData.txt").toPath());
            assertEquals(60 + 1, odo.size(), "a line per odometry event and the header");
            assertFalse(odo.get(1).contains("pending"));
        }
    }

    @Test
    void withoutAnAllocationCounterTheAreasUseIsNullNotZero() throws Exception {
        // A JVM with no per-thread allocation counter measured nothing, yet summary.json said the
        // scoped style's releases allocated 0 bytes, the preallocated style's claim.
        File ds = SyntheticDataset.write(new File(tmp, "ds"), 2.0, 3, true, true);
        File o = new File(tmp, "out");
        AllocationMeter installed = AllocationMeter.current();
        AllocationMeter.install(AllocationMeter.NONE);
        try {
            assertEquals(0, call.run("run", "--engine", "scj", "--memory", "scoped", "-p", "100", "--policy", "queue",
                    "--time-scale", "0.5", "--dataset", ds.getPath(), "-O", o.getPath()), call.err());
        } finally {
            AllocationMeter.install(installed);
        }
        String s = read(new File(new File(call.out().trim()), "summary.json"));
        assertTrue(s.contains("\"allocationMeter\": \"none\""), s);
        java.util.regex.Matcher update = java.util.regex.Pattern.compile("\"name\": \"update\",\\s*\"size\": \\d+,"
                + "\\s*\"peakBytes\": null,\\s*\"bytesPerRelease\": null,\\s*\"releases\": [1-9]\\d*,"
                + "\\s*\"allocatingReleases\": null").matcher(s);
        assertTrue(update.find(), s);
        assertTrue(s.contains("\"name\": \"mission\",") && !s.matches("(?s).*\"peakBytes\": \\d.*"), s);
    }

    @Test
    void everyRunSaysItsEngineIdealOnesToo() throws Exception {
        File ds = SyntheticDataset.write(new File(tmp, "ds"), 2.0, 3, true, true);
        File o = new File(tmp, "out");
        assertEquals(0, call.run("run", "--ideal", "-p", "50", "--dataset", ds.getPath(), "-O", o.getPath()),
                call.err());
        String s = read(new File(new File(call.out().trim()), "summary.json"));
        assertTrue(s.contains("\"engine\": \"javase\""), s);
        assertTrue(s.contains("\"kind\": \"javase\""), s);
        assertTrue(s.contains("\"name\": \"heap\""), s);
        assertEquals(0, call.run("run", "--ideal", "--engine", "scj", "-p", "50", "--dataset", ds.getPath(), "-O",
                o.getPath()), call.err());
        String scj = read(new File(new File(call.out().trim()), "summary.json"));
        assertTrue(scj.contains("\"kind\": \"scj\""), scj);
    }

    @Test
    void anUnknownEngineOrAMemoryStyleTheEngineLacksIsBadUsage() {
        assertEquals(2, call.run("run", "--engine", "jamaica"));
        assertTrue(call.err().startsWith("jmclbench: --engine: 'jamaica'"), call.err());
        assertEquals(1, call.err().trim().split("\n").length, call.err());
        assertEquals(2, call.run("run", "--engine", "scj", "--memory", "allocating"));
        assertTrue(call.err().startsWith("jmclbench: --memory:"), call.err());
        assertEquals(2, call.run("run", "--memory", "scoped"));
        assertTrue(call.err().startsWith("jmclbench: --memory:"), call.err());
        assertEquals(2, call.run("run", "--area-size", "mission=100000"));
        assertTrue(call.err().startsWith("jmclbench: --area-size:"), call.err());
        assertEquals(2, call.run("run", "--engine", "scj", "--area-size", "heap=100000"));
        assertTrue(call.err().contains("'heap' is not an area"), call.err());
        assertEquals(2, call.run("run", "--engine", "scj", "--area-size", "mission"));
    }

    @Test
    void odometryWithoutAPeriodIsBadInputNamingFileAndLine() throws Exception {
        call.assertRejectsAperiodicOdometry(tmp, "scj");
        File o = new File(tmp, "out");
        assertFalse(o.exists() && o.list().length > 0, "nothing recorded");
    }

    @Test
    void anAreaTooSmallFailsTheRunNamingTheAreaAndLeavesOnlyAPartialFolder() throws Exception {
        File ds = SyntheticDataset.write(new File(tmp, "ds"), 1.0, 3, true, true);
        File o = new File(tmp, "out");
        assertEquals(1, call.run("run", "--engine", "scj", "-p", "4000", "--dataset", ds.getPath(), "-O", o.getPath(),
                "-j", "t", "--area-size", "mission=70000"), call.err());
        assertTrue(call.err().startsWith("jmclbench: failure: memory area 'mission' overflowed"), call.err());
        assertTrue(call.err().contains("needed"), call.err());
        assertEquals(1, call.err().trim().split("\n").length, call.err());
        File test = new File(o, "t/nocov/4000/SkipTest");
        assertTrue(new File(test, "1.partial").isDirectory());
        assertFalse(new File(test, "1").exists());
    }
}
