package org.jmclbench.hvm.launcher;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.File;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.util.concurrent.TimeUnit;

import org.jmclbench.core.mcl.AbortSignal;
import org.jmclbench.core.mcl.Localizer;
import org.jmclbench.core.record.JobRecords;
import org.jmclbench.core.timeline.Timeline;
import org.jmclbench.scj.MissionConfiguration;
import org.jmclbench.scj.MissionRunFile;
import org.jmclbench.scj.MissionSizes;
import org.jmclbench.workload.RunOptions;
import org.jmclbench.workload.data.Dataset;
import org.jmclbench.workload.data.DatasetReader;
import org.jmclbench.workload.mcl.Localizers;
import org.jmclbench.workload.scj.ScjRun;
import org.jmclbench.workload.testing.SyntheticDataset;
import org.jmclbench.workload.testing.WorkloadCall;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The {@code --engine hvm} run (the SCJ mission on the icecap HVM). The tests that run the VM
 * need its tool chain (HVM_SRC, see docs/HVM.md) and are skipped without it; the others do not.
 */
class HvmRunTest {
    /** As IdealCrossCheckTest (Java vs C): a larger difference is a real divergence. */
    private static final double TOL = 1e-9;

    @TempDir
    File tmp;

    private final String home = System.getProperty("jmclbench.home");

    @org.junit.jupiter.api.AfterEach
    void restoreHome() {
        if (home == null) {
            System.clearProperty("jmclbench.home");
        } else {
            System.setProperty("jmclbench.home", home);
        }
    }

    private final WorkloadCall call = new WorkloadCall();

    /** The project folder above the working directory, or null. */
    static File projectHome() {
        File dir = new File("").getAbsoluteFile();
        while (dir != null && !new File(dir, "hvm/build-mission.sh").isFile()) {
            dir = dir.getParentFile();
        }
        return dir;
    }

    /** Points the workload at the project (for hvm/build-mission.sh) and skips when the tool chain cannot be built here. */
    static void assumeHvm() throws Exception {
        File home = projectHome();
        Assumptions.assumeTrue(home != null, "no hvm/ folder above the working directory");
        System.setProperty("jmclbench.home", home.getPath());
        Process p = new ProcessBuilder(new File(home, "hvm/build-hvm.sh").getPath(), "--check")
                .redirectErrorStream(true).start();
        String why = new String(readAll(p), StandardCharsets.UTF_8).trim();
        assertTrue(p.waitFor(60, TimeUnit.SECONDS), "build-hvm.sh --check hung");
        Assumptions.assumeTrue(p.exitValue() == 0 && System.getenv("HVM_SRC") != null,
                "the icecap HVM cannot be built here (set HVM_SRC): " + why);
    }

    @Test
    void anAreaIsNamedByTheSizeIcecapReports() {
        long[] sizes = {1200000, 300000, 4096, 2000, 4096};
        String full = HvmRun.overflow("x\nout of memory: 0x000007D0, 0x00000C84\n", sizes);
        assertEquals("memory area 'update' overflowed on the HVM: an allocation of 3204 bytes did not fit its 2000"
                + " bytes (--area-size AREA=BYTES)", full);
        assertTrue(HvmRun.overflow("out of memory: 0x00001000, 0x00000010", sizes).contains("'predict or sensor'"));
        assertTrue(HvmRun.overflow("out of memory: 0x00000100, 0x00000010", sizes).contains("icecap-internal"));
        assertNull(HvmRun.overflow("warning: unimplemented function executed [0x02EB]", sizes));
    }

    @Test
    void icecapsRoomIsAddedToComputedSizesOnlyAsDocsHvmSays() throws Exception {
        // An immortal size set with --area-size gained icecap's 1 MiB all the same: immortal=1000
        // ran, reported as a 1,049,576-byte area, the user's budget never applied.
        File ds = SyntheticDataset.write(new File(tmp, "ds-sizes"), 2.0, 3, true, true);
        Dataset d = DatasetReader.readFolder(ds);
        RunOptions set = org.jmclbench.workload.RunOptionsParser.parse(new String[] {"run", "--engine", "hvm",
            "--area-size", "immortal=1000", "--area-size", "mission=2000", "--dataset", ds.getPath()});
        long[] given = HvmRun.areaSizes(ScjRun.configuration(set, set.mclConfig(), 1.0, true), d);
        assertEquals(1000, given[MissionSizes.IMMORTAL]);
        assertEquals(2000, given[MissionSizes.MISSION]);
        RunOptions computed = org.jmclbench.workload.RunOptionsParser.parse(new String[] {"run", "--engine", "hvm",
            "--dataset", ds.getPath()});
        MissionConfiguration c = ScjRun.configuration(computed, computed.mclConfig(), 1.0, true);
        MissionSizes mission = new MissionSizes(c, d.odometryCount(), d.laserCount());
        long[] sizes = HvmRun.areaSizes(c, d);
        assertEquals(mission.size(MissionSizes.IMMORTAL) + MissionRunFile.IMMORTAL_INFRASTRUCTURE, sizes[MissionSizes.IMMORTAL]);
        assertEquals(mission.size(MissionSizes.MISSION) + MissionRunFile.HANDLER_STACKS, sizes[MissionSizes.MISSION]);
        assertEquals(mission.size(MissionSizes.UPDATE), sizes[MissionSizes.UPDATE]);
    }

    @Test
    void badInputIsRejectedBeforeAnythingIsBuilt() throws Exception {
        // No build script under this home: reaching the build would be a failure (1), not bad input (2).
        System.setProperty("jmclbench.home", tmp.getPath());
        File ds = call.assertRejectsAperiodicOdometry(tmp, "hvm");
        File o = new File(tmp, "out");
        assertEquals(2, call.run("run", "--engine", "hvm", "--memory", "allocating", "--dataset", ds.getPath()),
                call.err());
        assertEquals(2, call.run("run", "--engine", "hvm", "--area-size", "nursery=100", "--dataset", ds.getPath()),
                call.err());
        assertFalse(o.exists() && o.list().length > 0, "nothing recorded");
    }

    @Test
    void areasTheHeapCannotHoldAreUnsupportedBeforeAnythingIsBuilt() throws Exception {
        // run-hvm --area-size mission=2000000000 built the executable, then failed (exit 1) with
        // "memory area of 268435456 bytes (an icecap-internal area) overflowed ... 22 bytes"
        File project = projectHome();
        Assumptions.assumeTrue(project != null, "no hvm/ folder above the working directory");
        // the project's heap, and no build script: reaching the build would be a failure (1)
        File hvm = new File(tmp, "hvm");
        assertTrue(hvm.mkdirs());
        java.nio.file.Files.copy(new File(project, HvmLimits.HEAP_FILE).toPath(), new File(hvm, "hvm.properties").toPath());
        System.setProperty("jmclbench.home", tmp.getPath());
        File ds = SyntheticDataset.write(new File(tmp, "ds-heap"), 2.0, 3, true, true);
        File o = new File(tmp, "out");
        assertEquals(3, call.run("run", "--engine", "hvm", "--area-size", "mission=2000000000", "--dataset", ds.getPath(),
                "-O", o.getPath()), call.err());
        assertTrue(call.err().matches("jmclbench: unsupported: --area-size: the SCJ backing store of these areas is"
                + " 8,00[0-9,]+ bytes, more than the HVM's heap holds \\([0-9,]+ bytes of its [0-9,]+,"
                + " hvm/hvm.properties; docs/HVM.md\\)\n"), call.err());
        assertFalse(o.exists(), "nothing recorded");
        // one the heap holds goes on to the build
        assertEquals(1, call.run("run", "--engine", "hvm", "--area-size", "mission=60000000", "--dataset", ds.getPath(),
                "-O", o.getPath()), call.err());
        assertTrue(call.err().contains("build-mission.sh"), call.err());
    }

    @Test
    void aQueueRunAgreesWithTheIdealComputationOfItsJobs() throws Exception {
        assumeHvm();
        // Under queue every job runs to completion, so each estimate depends only on the jobs
        // before it. The HVM releases on a 1 ms tick and the machine's load decides overlaps, so
        // its order can differ from the timeline's (two events a tick apart run in priority
        // order): replay on the JVM, with the one Java MCL, the jobs in the order the HVM
        // started them, and compare every estimate. Independent of load by construction.
        // Particles and memory style can be set for a longer check (-Djmclbench.hvmtest.particles=400,
        // -Djmclbench.hvmtest.memory=scoped); the executable's mode follows JMCLBENCH_HVM_MODE.
        File home = projectHome();
        RunOptions o = org.jmclbench.workload.RunOptionsParser.parse(new String[] {"run", "--engine", "hvm", "-p",
            System.getProperty("jmclbench.hvmtest.particles", "50"), "--memory",
            System.getProperty("jmclbench.hvmtest.memory", "preallocated"), "--policy", "queue", "--dataset",
            new File(home, "data/match-short").getPath()});
        Dataset d = DatasetReader.readFolder(new File(home, "data/match-short"));
        File folder = new File(tmp, "run");
        folder.mkdirs();
        org.jmclbench.workload.engine.EngineResult result = HvmRun.run(o, d, folder, System.err);
        JobRecords r = result.records;
        for (org.jmclbench.workload.output.MemoryArea a : result.areas) {
            // the store rejects a negative byte count: a peak the VM does not keep is null
            assertTrue(a.peakBytes == null || a.peakBytes >= 0, a.name + " peak " + a.peakBytes);
        }

        Integer[] order = new Integer[r.size()];
        for (int k = 0; k < order.length; k++) {
            assertTrue(r.completed(k), "queue: event " + k + " completed");
            order[k] = k;
        }
        java.util.Arrays.sort(order, (a, b) -> Long.compare(r.startNs[a], r.startNs[b]));
        Localizer l = Localizers.create(o.mclConfig(), d.playground, d.startX, d.startY, d.startTheta);
        assertEquals(l.estimateX(), r.initialX, TOL, "initial x");
        Timeline t = r.timeline;
        int reordered = 0;
        for (int n = 0; n < order.length; n++) {
            int k = order[n];
            reordered += k != n ? 1 : 0;
            int i = t.taskIndex(k);
            if (t.task(k) == Timeline.PREDICT) {
                l.predict(d.odoDx[i], d.odoDy[i], d.odoDtheta[i], AbortSignal.NEVER);
            } else {
                l.update(d.laserAngle[i], AbortSignal.NEVER);
            }
            assertEquals(l.estimateX(), r.estX[k], TOL, "x after event " + k + " (job " + n + " on the HVM)");
            assertEquals(l.estimateY(), r.estY[k], TOL, "y after event " + k);
            double dt = Math.abs(l.estimateTheta() - r.estTheta[k]);
            assertTrue(Math.min(dt, 2 * Math.PI - dt) <= TOL, "theta after event " + k);
        }
        System.out.println("HvmRunTest (" + ((HvmFacts) result.facts).mode() + ", " + o.mclConfig().particles
                + " particles, " + o.memory + "): " + order.length + " jobs agree; " + reordered
                + " ran out of the timeline's order (1 ms tick, load)");
    }

    @Test
    void eachPrivateMemorysUseIsMeasuredOnTheHvmPerRelease() throws Exception {
        assumeHvm();
        // icecap empties a private memory after each release and keeps no peak: the mission's
        // output reads it as each release ends. Allocation is deterministic, so exact counts hold.
        int n = 400;
        File ds = SyntheticDataset.write(new File(tmp, "ds-areas"), 2.0, 3, true, true);
        Dataset d = DatasetReader.readFolder(ds);
        for (String memory : new String[] {"scoped", "preallocated"}) {
            RunOptions o = org.jmclbench.workload.RunOptionsParser.parse(new String[] {"run", "--engine", "hvm", "-p",
                String.valueOf(n), "--memory", memory, "--policy", "queue", "--dataset", ds.getPath()});
            File folder = new File(tmp, "areas-" + memory);
            folder.mkdirs();
            java.util.Map<String, org.jmclbench.workload.output.MemoryArea> areas = new java.util.HashMap<>();
            for (org.jmclbench.workload.output.MemoryArea a : HvmRun.run(o, d, folder, System.err).areas) {
                areas.put(a.name, a);
            }
            for (String handler : new String[] {"predict", "update", "sensor"}) {
                org.jmclbench.workload.output.MemoryArea a = areas.get(handler);
                assertTrue(a.releases != null && a.releases > 0, memory + " " + handler + ": no release measured");
                boolean allocates = memory.equals("scoped") && !handler.equals("sensor");
                // scoped: a predict release allocates three particle arrays, an update release at least five
                long temporaries = handler.equals("predict") ? 24L * n : 36L * n;
                assertEquals(allocates ? a.releases : Long.valueOf(0), a.allocatingReleases, memory + " " + handler);
                assertTrue(allocates ? a.peakBytes >= temporaries && a.peakBytes <= a.size : a.peakBytes == 0,
                        memory + " " + handler + " largest release " + a.peakBytes);
            }
            assertNull(areas.get("mission").releases, "releases apply to private memories only");
        }
    }

    @Test
    void aPrivateMemoryTooSmallFailsWithTheAreaNamed() throws Exception {
        assumeHvm();
        File ds = SyntheticDataset.write(new File(tmp, "ds"), 2.0, 3, true, true);
        File o = new File(tmp, "out");
        assertEquals(1, call.run("run", "--engine", "hvm", "--memory", "scoped", "--area-size", "update=2000",
                "-p", "400", "--policy", "queue", "--dataset", ds.getPath(), "-O", o.getPath()), call.err());
        assertTrue(call.err().contains("memory area 'update' overflowed"), call.err());
        assertFalse(new File(o, "hvm/nocov/400/QueueTest/1/summary.json").exists(), "nothing recorded as valid");
    }

    @Test
    void anImmortalMemorySetTooSmallFailsWithTheAreaNamed() throws Exception {
        assumeHvm();
        File ds = SyntheticDataset.write(new File(tmp, "ds"), 2.0, 3, true, true);
        File o = new File(tmp, "out");
        assertEquals(1, call.run("run", "--engine", "hvm", "--area-size", "immortal=1000", "-p", "50", "--policy",
                "queue", "--dataset", ds.getPath(), "-O", o.getPath()), call.err());
        assertTrue(call.err().contains("memory area 'immortal' overflowed"), call.err());
        assertFalse(new File(o, "hvm/nocov/50/QueueTest/1/summary.json").exists(), "nothing recorded as valid");
    }

    /** Everything a process wrote on its standard output. */
    static byte[] readAll(Process p) throws IOException {
        ByteArrayOutputStream b = new ByteArrayOutputStream();
        byte[] buf = new byte[4096];
        for (int n; (n = p.getInputStream().read(buf)) > 0;) {
            b.write(buf, 0, n);
        }
        return b.toByteArray();
    }
}
