package org.jmclbench.hvm.launcher;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;

import org.jmclbench.core.record.JobRecords;
import org.jmclbench.core.timeline.Timeline;
import org.jmclbench.scj.MissionRunFile;
import org.jmclbench.scj.MissionSizes;
import org.jmclbench.workload.RunFailure;
import org.jmclbench.workload.output.MemoryArea;
import org.junit.jupiter.api.Test;

import com.code_intelligence.jazzer.junit.FuzzTest;

/**
 * The HVM result file's reader under Jazzer: whatever bytes an executable leaves, the reader
 * returns records of ended jobs or refuses the file with one line naming it; any other
 * exception, or an accepted record that is not an ended job, is a finding. A normal test run
 * replays the kept inputs ({@code HvmResultFileFuzzTestInputs/}); JAZZER_FUZZ=1 or
 * bench/fuzz.sh fuzzes.
 */
class HvmResultFileFuzzTest {
    /** Three odometry and two laser events: five jobs. */
    static final Timeline TIMELINE = Timeline.merge(new double[] {0.05, 0.10, 0.15}, new double[] {0.07, 0.12});

    /** The first byte says whether the run computed the covariance; the rest is the file. */
    @FuzzTest(maxDuration = "10m")
    void resultFile(byte[] data) throws IOException {
        if (data.length == 0) {
            return;
        }
        boolean covariance = (data[0] & 1) != 0;
        byte[] file = Arrays.copyOfRange(data, 1, data.length);
        HvmResultFile.AreaUse use = new HvmResultFile.AreaUse();
        JobRecords r;
        try {
            r = HvmResultFile.read(new ByteArrayInputStream(file), "result.bin", TIMELINE, covariance, use);
        } catch (RunFailure e) {
            assertTrue(e.getMessage().startsWith("the HVM's result file result.bin: "), e.getMessage());
            assertFalse(e.getMessage().contains("\n"), e.getMessage());
            return;
        }
        for (int k = 0; k < r.size(); k++) {
            assertTrue(r.outcome[k] >= JobRecords.DONE && r.outcome[k] <= JobRecords.TERMINATED, "outcome " + r.outcome[k]);
            assertTrue(r.releaseNs[k] >= -1 && r.startNs[k] >= -1 && r.endNs[k] >= -1 && r.abortNs[k] >= -1);
            if (r.completed(k)) {
                assertTrue(r.startNs[k] >= 0 && r.endNs[k] >= r.startNs[k]);
            }
        }
        assertTrue(r.durationNs >= 0);
        assertEquals(covariance, r.cov != null);
        for (int a = MissionSizes.PREDICT; a < MissionSizes.AREA_COUNT; a++) {
            MemoryArea area = use.area(a, 1 << 20);
            if (area.releases != null) {
                assertTrue(area.allocatingReleases <= area.releases && area.bytesPerRelease <= area.peakBytes, area.name);
            }
        }
    }

    @Test
    void aWellFormedFileIsReadWordForWord() throws Exception {
        byte[] file = valid(false);
        HvmResultFile.AreaUse use = new HvmResultFile.AreaUse();
        JobRecords r = HvmResultFile.read(new ByteArrayInputStream(file), "result.bin", TIMELINE, false, use);
        assertEquals(5, r.size());
        assertEquals(JobRecords.DONE, r.outcome[0]);
        assertEquals(JobRecords.SKIPPED, r.outcome[4]);
        assertEquals(1_000_000L, r.durationNs);
        assertEquals(50_500_000L, r.abortNs[1]);
        assertEquals(-1, r.abortNs[0]);
        assertEquals(50_520_000L, r.abortSeenNs[1]);
        assertEquals(-1, r.abortSeenNs[0]);
        MemoryArea mission = use.area(MissionSizes.MISSION, 8192);
        assertEquals(4096L, mission.peakBytes);
        assertEquals(null, mission.releases, "releases apply to a handler's private memory only");
        MemoryArea predict = use.area(MissionSizes.PREDICT, 8192);
        assertEquals(0L, predict.peakBytes);
        assertEquals(3L, predict.releases);
        assertEquals(0L, predict.allocatingReleases);
        assertEquals(0L, predict.bytesPerRelease);
        MemoryArea update = use.area(MissionSizes.UPDATE, 8192);
        assertEquals(3204L, update.peakBytes);
        assertEquals(2L, update.releases);
        assertEquals(2L, update.allocatingReleases);
        assertEquals(3100L, update.bytesPerRelease);
    }

    @Test
    void everyDefectIsOneLineNamingTheFile() throws Exception {
        byte[] good = valid(false);
        assertRefused("truncated", Arrays.copyOf(good, good.length - 3));
        byte[] longer = Arrays.copyOf(good, good.length + 1);
        assertRefused("bytes after the end of the records", longer);
        byte[] outcome = good.clone();
        putWord(outcome, 4 + 5 * 5 + 1, 9); // event 1's outcome
        assertRefused("event 1: outcome 9 is not a code of an ended job", outcome);
        byte[] pending = good.clone();
        putWord(pending, 4 + 5 * 5 + 2, JobRecords.PENDING);
        assertRefused("event 2 never ended on the HVM (the mission terminated early)", pending);
        byte[] time = good.clone();
        putWord(time, 4, -7); // event 0's release
        assertRefused("event 0: time -7 (ns are >= 0, -1 for none)", time);
        assertRefused("covariance flag 0, expected 1", good, true);
        byte[] section = good.clone();
        putWord(section, 4 + 5 * 6, 7); // the abort section's code
        assertRefused("word 7 where the abort section's code belongs", section);
        byte[] abort = good.clone();
        putWord(abort, 4 + 5 * 6 + 1 + 3, -2); // event 3's abort request
        assertRefused("event 3: time -2 (ns are >= 0, -1 for none)", abort);
        int releaseSection = good.length / 8 - 1 - 3 * 3;
        byte[] releases = good.clone();
        putWord(releases, releaseSection, 5);
        assertRefused("word 5 where the release section's code belongs", releases);
        byte[] allocating = good.clone();
        putWord(allocating, releaseSection + 1 + 3 + 1, 3); // update: 3 of its 2 releases allocated
        assertRefused("area update: 2 releases, 3 of them allocating 6200 bytes, the largest 3204 bytes: these do not agree", allocating);
        byte[] beyondLargest = good.clone();
        putWord(beyondLargest, releaseSection + 1 + 3 + 2, 6409); // more than two releases of 3204 bytes
        assertRefused("area update: 2 releases, 2 of them allocating 6409 bytes, the largest 3204 bytes: these do not agree", beyondLargest);
    }

    @Test
    void aPrivateMemorysCountsAgreeOnlyWhenOneRunCanHaveMadeThem() {
        assertTrue(HvmResultFile.agree(0, 5, 0, 0), "no release allocated");
        assertTrue(HvmResultFile.agree(100, 5, 2, 150));
        assertTrue(HvmResultFile.agree(100, 5, 2, 200), "both at the largest");
        assertFalse(HvmResultFile.agree(100, 5, 2, 201), "more than two releases of at most 100 bytes");
        assertFalse(HvmResultFile.agree(100, 5, 2, 1), "an allocating release allocates at least a byte each");
        assertFalse(HvmResultFile.agree(0, 5, 1, 10), "a largest release of 0 bytes with an allocating one");
        assertFalse(HvmResultFile.agree(10, 5, 0, 0), "a largest release of 10 bytes, none allocating");
        assertFalse(HvmResultFile.agree(-1, 5, 0, 0), "an unknown largest release");
        // 2 * largest overflows a long; the check must not
        assertTrue(HvmResultFile.agree(Long.MAX_VALUE, 3, 2, Long.MAX_VALUE));
        assertFalse(HvmResultFile.agree(Long.MAX_VALUE / 2, 3, 2, Long.MAX_VALUE));
    }

    /** Keeps a valid file among the kept inputs (run once by hand after a layout change). */
    public static void main(String[] args) throws IOException {
        Path dir = java.nio.file.Paths.get("src/test/resources/org/jmclbench/hvm/launcher/HvmResultFileFuzzTestInputs/resultFile");
        Files.createDirectories(dir);
        Files.write(dir.resolve("valid-without-covariance"), withFlag(0, valid(false)));
        Files.write(dir.resolve("valid-with-covariance"), withFlag(1, valid(true)));
    }

    private static byte[] withFlag(int flag, byte[] file) {
        byte[] out = new byte[file.length + 1];
        out[0] = (byte) flag;
        System.arraycopy(file, 0, out, 1, file.length);
        return out;
    }

    private static void assertRefused(String problem, byte[] file) {
        assertRefused(problem, file, false);
    }

    private static void assertRefused(String problem, byte[] file, boolean covariance) {
        RunFailure e = assertThrows(RunFailure.class, () -> HvmResultFile.read(new ByteArrayInputStream(file), "result.bin",
                TIMELINE, covariance, new HvmResultFile.AreaUse()));
        assertEquals("the HVM's result file result.bin: " + problem, e.getMessage());
    }

    private static void putWord(byte[] file, int word, long v) {
        for (int b = 0; b < 8; b++) {
            file[word * 8 + b] = (byte) (v >>> (8 * b));
        }
    }

    /** A result file as HvmOutput writes it for {@link #TIMELINE}: four jobs done (job 1 asked to abort), the last one skipped. */
    static byte[] valid(boolean covariance) throws IOException {
        ByteArrayOutputStream b = new ByteArrayOutputStream();
        int n = TIMELINE.size();
        long[] words = {MissionRunFile.OUTPUT_MAGIC, MissionRunFile.VERSION, n, covariance ? 1 : 0};
        for (long w : words) {
            word(b, w);
        }
        for (int column = 0; column < 5; column++) { // release, start, end, deadline, wake
            for (int k = 0; k < n; k++) {
                boolean ran = k < n - 1;
                long release = 50_000_000L * k;
                long[] value = {release, ran ? release + 1000 : -1, ran ? release + 900_000 : -1, release + 50_000_000L, release};
                word(b, value[column]);
            }
        }
        for (int k = 0; k < n; k++) {
            word(b, k < n - 1 ? JobRecords.DONE : JobRecords.SKIPPED);
        }
        word(b, MissionRunFile.ABORT_SECTION);
        for (int k = 0; k < n; k++) {
            word(b, k == 1 ? 50_000_000L * k + 500_000 : -1); // job 1 asked to abort mid-way
        }
        for (int k = 0; k < n; k++) {
            word(b, k == 1 ? 50_000_000L * k + 520_000 : -1); // and saw it 20 us later
        }
        for (int i = 0; i < 3 * n + (covariance ? 6 * n : 0) + 3; i++) {
            word(b, Double.doubleToRawLongBits(0.25 * i));
        }
        word(b, 1_000_000L);
        // the areas' uses: immortal and mission at the end, then each private memory's largest release
        for (long use : new long[] {4096, 4096, 0, 3204, 0}) {
            word(b, use);
        }
        word(b, MissionRunFile.RELEASE_SECTION);
        // releases, allocating releases, bytes: predict and sensor allocate nothing, update 2996 + 3204
        for (long w : new long[] {3, 0, 0, 2, 2, 6200, 2, 0, 0}) {
            word(b, w);
        }
        return b.toByteArray();
    }

    private static void word(ByteArrayOutputStream b, long v) {
        for (int i = 0; i < 8; i++) {
            b.write((int) (v >>> (8 * i)));
        }
    }
}
