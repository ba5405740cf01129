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
        long[] peaks = new long[MissionSizes.AREA_COUNT];
        JobRecords r;
        try {
            r = HvmResultFile.read(new ByteArrayInputStream(file), "result.bin", TIMELINE, covariance, peaks);
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
    }

    @Test
    void aWellFormedFileIsReadWordForWord() throws Exception {
        byte[] file = valid(false);
        long[] peaks = new long[MissionSizes.AREA_COUNT];
        JobRecords r = HvmResultFile.read(new ByteArrayInputStream(file), "result.bin", TIMELINE, false, peaks);
        assertEquals(5, r.size());
        assertEquals(JobRecords.DONE, r.outcome[0]);
        assertEquals(JobRecords.SKIPPED, r.outcome[4]);
        assertEquals(1_000_000L, r.durationNs);
        assertEquals(50_500_000L, r.abortNs[1]);
        assertEquals(-1, r.abortNs[0]);
        assertEquals(50_520_000L, r.abortSeenNs[1]);
        assertEquals(-1, r.abortSeenNs[0]);
        assertEquals(-1, peaks[MissionSizes.PREDICT]);
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
                TIMELINE, covariance, new long[MissionSizes.AREA_COUNT]));
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
        for (int a = 0; a < MissionSizes.AREA_COUNT; a++) {
            word(b, a < MissionSizes.PREDICT ? 4096 : -1);
        }
        return b.toByteArray();
    }

    private static void word(ByteArrayOutputStream b, long v) {
        for (int i = 0; i < 8; i++) {
            b.write((int) (v >>> (8 * i)));
        }
    }
}
