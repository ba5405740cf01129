package org.jmclbench.workload.rtsj;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.File;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

import org.jmclbench.workload.RunOptions;
import org.jmclbench.workload.release.ThreadCpuClock;
import org.jmclbench.workload.shim.CpuClock;
import org.jmclbench.workload.testing.SyntheticDataset;
import org.jmclbench.workload.testing.WorkloadCall;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** {@code --engine rtsj}: its run folder, its facts in summary.json, and its bad input. */
class RtsjEngineTest {
    @TempDir
    File tmp;

    private final WorkloadCall call = new WorkloadCall();

    @Test
    void eachDesignWritesItsOwnRunFolderAndEveryEventEnds() throws Exception {
        File ds = SyntheticDataset.write(new File(tmp, "ds"), 2.0, 3, true, true);
        File o = new File(tmp, "out");
        for (String design : new String[] {"thesis", "atomic"}) {
            for (String policy : new String[] {"queue", "terminate"}) {
                assertEquals(0, call.run("run", "--engine", "rtsj", "--rtsj-design", design, "--policy", policy, "-p",
                        "100", "--time-scale", "0.5", "--dataset", ds.getPath(), "-O", o.getPath()), call.err());
                File dir = new File(call.out().trim());
                String runtime = RunOptions.defaultRuntimeName() + "-rtsj-" + design;
                assertTrue(dir.getPath().startsWith(new File(o, runtime).getPath()), dir.getPath());
                String s = new String(Files.readAllBytes(new File(dir, "summary.json").toPath()), StandardCharsets.UTF_8);
                assertTrue(s.contains("\"kind\": \"rtsj\""), s);
                assertTrue(s.contains("\"design\": \"" + design + "\""), s);
                assertTrue(s.contains("\"abortLatencyNs\""), s);
                assertFalse(s.contains("pending"), s);
                if (policy.equals("queue")) {
                    assertTrue(s.contains("\"skipped\": 0") && s.contains("\"terminated\": 0"), s);
                }
            }
        }
    }

    /**
     * On a JVM every job that ran, completed or aborted, has its CPU time (cpu_ns >= 0) and
     * summary.json says how it was read; with {@code --no-cpu-time} none has one and the engine's
     * clock is off. A JVM without a usable clock gives -1 and says why.
     */
    @Test
    void jobsThatRanCarryTheirCpuTimeUnlessNoCpuTime() throws Exception {
        File ds = SyntheticDataset.write(new File(tmp, "ds"), 2.0, 3, true, true);
        ThreadCpuClock clock = ThreadCpuClock.probe();
        String[][] runs = {{"queue", "thesis"}, {"terminate", "atomic"}, {"terminate", "atomic", "--no-cpu-time"}};
        for (String[] r : runs) {
            List<String> args = new ArrayList<>(Arrays.asList("run", "--engine", "rtsj", "--policy", r[0],
                    "--rtsj-design", r[1], "-p", "100", "--time-scale", "0.5", "--dataset", ds.getPath(),
                    "-O", new File(tmp, "out").getPath(), "--force"));
            args.addAll(Arrays.asList(r).subList(2, r.length));
            boolean off = args.contains("--no-cpu-time");
            assertEquals(0, call.run(args.toArray(new String[0])), args + ": " + call.err());
            File dir = new File(call.out().trim());
            int ran = 0;
            int measured = 0;
            for (String f : new String[] {"odoData.txt", "laserData.txt"}) {
                for (String line : Files.readAllLines(new File(dir, f).toPath(), StandardCharsets.UTF_8)) {
                    String[] c = line.split(" ");
                    if (line.startsWith("#")) {
                        continue;
                    }
                    long cpu = Long.parseLong(c[6]);
                    if (Long.parseLong(c[2]) < 0) {
                        assertEquals(-1, cpu, args + ": a job that never started has no CPU time: " + line);
                        continue;
                    }
                    ran++;
                    measured += cpu >= 0 ? 1 : 0;
                }
            }
            assertTrue(ran > 0, args + ": no job ran");
            assertEquals(off || !clock.usable() ? 0 : ran, measured, args + ": jobs with a CPU time");
            String s = new String(Files.readAllBytes(new File(dir, "summary.json").toPath()), StandardCharsets.UTF_8);
            assertTrue(s.contains("\"cpuTime\": " + !off), args + ": parameters.cpuTime");
            String status = off ? CpuClock.OFF : clock.status();
            assertTrue(s.contains("\"cpuTime\": \"" + status + "\""), args + ": engine.cpuTime " + status + "\n" + s);
        }
    }

    @Test
    void optionsOfTheDesignAreBadUsageElsewhere() {
        assertEquals(2, call.run("run", "--rtsj-design", "atomic"));
        assertTrue(call.err().startsWith("jmclbench: --rtsj-design: chooses the rtsj engine's design"), call.err());
        assertEquals(2, call.run("run", "--engine", "rtsj", "--rtsj-design", "fast"));
        assertTrue(call.err().startsWith("jmclbench: --rtsj-design: 'fast' is not one of thesis|atomic"), call.err());
        assertEquals(2, call.run("run", "--engine", "rtsj", "--memory", "scoped"));
        assertTrue(call.err().startsWith("jmclbench: --memory: 'scoped' is not a memory style of the rtsj engine"), call.err());
        assertEquals(1, call.err().trim().split("\n").length, call.err());
    }
}
