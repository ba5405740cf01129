package org.jmclbench.hvm.launcher;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.File;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.StandardCopyOption;
import java.util.concurrent.TimeUnit;

import org.jmclbench.core.mcl.MclConfig;
import org.jmclbench.scj.MissionRunFile;
import org.jmclbench.scj.MissionSizes;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The HVM's limits at their boundaries, which were measured on the VM (docs/HVM.md): 65,535
 * particles run and 65,536 crash; the scoped style is right at 8,191 and wrong at 8,192.
 */
class HvmLimitsTest {
    @TempDir
    File tmp;

    private static MclConfig filter(int particles, MclConfig.Memory memory, boolean covariance) {
        return MclConfig.builder().particles(particles).memory(memory).covariance(covariance).build();
    }

    @Test
    void theLastCountThatRanIsAllowedAndTheFirstThatFailedIsNot() {
        assertNull(HvmLimits.beyond(filter(65_535, MclConfig.Memory.PREALLOCATED, false), 574));
        assertTrue(HvmLimits.beyond(filter(65_536, MclConfig.Memory.PREALLOCATED, false), 574)
                .startsWith("--particles 65536: the HVM holds at most 65,535 particles"));
        assertNull(HvmLimits.beyond(filter(8_191, MclConfig.Memory.SCOPED, false), 574));
        assertTrue(HvmLimits.beyond(filter(8_192, MclConfig.Memory.SCOPED, false), 574)
                .startsWith("--particles 8192: the HVM runs the scoped memory style with at most 8,191 particles"));
    }

    @Test
    void aDatasetWhoseRecordsOutgrowTheArraysIsNamedWithTheOptionThatGrowsThem() {
        MclConfig plain = filter(400, MclConfig.Memory.PREALLOCATED, false);
        assertNull(HvmLimits.beyond(plain, 65_535));
        assertTrue(HvmLimits.beyond(plain, 65_536).startsWith("the dataset's 65,536 events"));
        MclConfig covariance = filter(400, MclConfig.Memory.PREALLOCATED, true);
        assertNull(HvmLimits.beyond(covariance, 10_922));
        assertTrue(HvmLimits.beyond(covariance, 10_923).startsWith("-c: the covariance of the dataset's 10,923 events"));
    }

    @Test
    void theAreasBackingStoreMustFitTheHeapLessItsReserve() {
        // run-hvm --area-size mission=2000000000 failed at launch: "memory area of 268435456 bytes
        // (an icecap-internal area) overflowed ... an allocation of 22 bytes", and HvmMain's int
        // sizes wrapped
        long[] sizes = new long[MissionSizes.AREA_COUNT];
        sizes[MissionSizes.IMMORTAL] = 2_000_000;
        sizes[MissionSizes.MISSION] = 1_000_000;
        sizes[MissionSizes.PREDICT] = sizes[MissionSizes.UPDATE] = sizes[MissionSizes.SENSOR] = 4096;
        long store = MissionRunFile.overallBackingStore(sizes);
        assertEquals(2_000_000 + 2 * (2_000_000 + 3 * 4096) + MissionRunFile.NESTING_SLACK
                + MissionRunFile.IDLE_BACKING_STORE, store);
        long heap = store + HvmLimits.HEAP_RESERVE;
        assertNull(HvmLimits.beyondHeap(sizes, heap, true));
        assertEquals(String.format(java.util.Locale.ROOT, "--area-size: the SCJ backing store of these areas is %,d"
                + " bytes, more than the HVM's heap holds (%,d bytes of its %,d, hvm/hvm.properties; docs/HVM.md)",
                store, store - 1, heap - 1), HvmLimits.beyondHeap(sizes, heap - 1, true));
        assertTrue(HvmLimits.beyondHeap(sizes, heap - 1, false).startsWith("the computed area sizes: "));
        assertNull(HvmLimits.beyondHeap(sizes, -1, true), "no heap known: the build says what is missing");
        // icecap's sizes are ints, whatever the heap
        sizes[MissionSizes.MISSION] = 600_000_000;
        assertTrue(HvmLimits.beyondHeap(sizes, 1L << 40, true).contains("2,147,483,647 bytes of its"));
    }

    @Test
    void theHeapIsTheOneOfHvmPropertiesAsTheBuildScriptReadsIt() throws Exception {
        File home = HvmRunTest.projectHome();
        Assumptions.assumeTrue(home != null, "no hvm/ folder above the working directory");
        assertTrue(HvmLimits.heapBytes(home) > HvmLimits.HEAP_RESERVE, "the project's heap");
        File hvm = new File(tmp, "hvm");
        assertTrue(hvm.mkdirs());
        assertEquals(-1, HvmLimits.heapBytes(tmp), "no file");
        for (String bad : new String[] {"heap=12x\n", "heap = 1000\n", "heap=1000\nheap=2000\n", "heap=\n"}) {
            Files.write(new File(hvm, "hvm.properties").toPath(), bad.getBytes(StandardCharsets.US_ASCII));
            assertEquals(-1, HvmLimits.heapBytes(tmp), bad);
        }
        Files.write(new File(hvm, "hvm.properties").toPath(), "# a comment\nheap=1000\n".getBytes(StandardCharsets.US_ASCII));
        assertEquals(1000, HvmLimits.heapBytes(tmp));
        // the build script reads the same line: a copy of it beside a malformed file refuses it
        for (String script : new String[] {"build-mission.sh", "script-options.sh"}) {
            Files.copy(new File(home, "hvm/" + script).toPath(), new File(hvm, script).toPath(),
                    StandardCopyOption.COPY_ATTRIBUTES);
        }
        Files.write(new File(hvm, "hvm.properties").toPath(), "heap=12x\n".getBytes(StandardCharsets.US_ASCII));
        Process p = new ProcessBuilder(new File(hvm, "build-mission.sh").getPath()).redirectOutput(new File(tmp, "out"))
                .redirectError(new File(tmp, "err")).start();
        assertTrue(p.waitFor(60, TimeUnit.SECONDS), "build-mission.sh hung");
        String err = new String(Files.readAllBytes(new File(tmp, "err").toPath()), StandardCharsets.UTF_8);
        assertEquals(2, p.exitValue(), err);
        assertEquals("build-mission: hvm/hvm.properties: heap: '12x' is not a positive number of bytes\n", err);
    }
}
