package org.jmclbench.hvm.launcher;

import java.io.DataInputStream;
import java.io.EOFException;
import java.io.IOException;
import java.io.InputStream;

import org.jmclbench.core.record.JobRecords;
import org.jmclbench.core.timeline.Timeline;
import org.jmclbench.scj.MissionRunFile;
import org.jmclbench.scj.MissionSizes;
import org.jmclbench.workload.RunFailure;
import org.jmclbench.workload.output.MemoryArea;

/**
 * The reader of the HVM's result file (docs/HVM.md, "Result file"): the job records the
 * mission wrote, checked word by word, so that nothing a crashed or wrong executable leaves
 * behind is recorded as a valid run. Anything but exactly the layout of
 * {@link MissionRunFile} for the run's events is a {@link RunFailure} with one line naming the
 * file: a wrong magic or version, another event count or covariance flag, an outcome that is not
 * a code of an ended job, a missing abort or release section code, a time below -1, a completed job without a start or ending before it, a
 * negative duration, an area use below -1, a private memory's releases that do not agree with its use, a file cut short or one
 * with bytes after its end.
 */
final class HvmResultFile {
    private final DataInputStream in;
    private final String name;

    private HvmResultFile(InputStream in, String name) {
        this.in = new DataInputStream(in);
        this.name = name;
    }

    /** Each memory area's use as the executable measured it, by {@link MissionSizes} index. */
    static final class AreaUse {
        /** Immortal and mission memory: what they held when the mission ended (their peak); a private memory: its largest release. */
        final long[] peakBytes = new long[MissionSizes.AREA_COUNT];
        /** A private memory's releases, those that allocated, and the bytes they allocated in all (0 for immortal and mission). */
        final long[] releases = new long[MissionSizes.AREA_COUNT];
        final long[] allocatingReleases = new long[MissionSizes.AREA_COUNT];
        final long[] allocatedBytes = new long[MissionSizes.AREA_COUNT];

        /** Area {@code a} for summary.json, given the size icecap was given. */
        MemoryArea area(int a, long size) {
            Long peak = peakBytes[a] < 0 ? null : Long.valueOf(peakBytes[a]);
            if (releases[a] == 0) {
                return new MemoryArea(MissionSizes.AREA_NAMES[a], size, peak, null);
            }
            return new MemoryArea(MissionSizes.AREA_NAMES[a], size, peak, Math.round((double) allocatedBytes[a] / releases[a]),
                    releases[a], allocatingReleases[a]);
        }
    }

    /**
     * The records of the events of {@code timeline}, read from {@code in}; each area's use as the
     * executable measured it goes into {@code use}.
     *
     * @param name what messages call the file
     */
    static JobRecords read(InputStream in, String name, Timeline timeline, boolean covariance, AreaUse use)
            throws RunFailure, IOException {
        return new HvmResultFile(in, name).records(timeline, covariance, use);
    }

    private JobRecords records(Timeline timeline, boolean covariance, AreaUse use) throws RunFailure, IOException {
        JobRecords r = new JobRecords(timeline, covariance);
        try {
            if (word() != MissionRunFile.OUTPUT_MAGIC || word() != MissionRunFile.VERSION) {
                throw fail("not a jmclbench result (magic or version)");
            }
            long n = word();
            long cov = word();
            if (n != r.size()) {
                throw fail("the HVM returned " + n + " events, expected " + r.size());
            }
            if (cov != (covariance ? 1 : 0)) {
                throw fail("covariance flag " + cov + ", expected " + (covariance ? 1 : 0));
            }
            for (long[] a : new long[][] {r.releaseNs, r.startNs, r.endNs, r.deadlineNs, r.wakeNs}) {
                for (int k = 0; k < n; k++) {
                    a[k] = time(k);
                }
            }
            for (int k = 0; k < n; k++) {
                r.outcome[k] = outcome(k, r);
                r.cpuNs[k] = -1; // SCJ has no per-thread CPU clock
            }
            long section = word();
            if (section != MissionRunFile.ABORT_SECTION) {
                throw fail("word " + Long.toHexString(section) + " where the abort section's code belongs");
            }
            for (long[] a : new long[][] {r.abortNs, r.abortSeenNs}) {
                for (int k = 0; k < n; k++) {
                    a[k] = time(k);
                }
            }
            for (double[] a : new double[][] {r.estX, r.estY, r.estTheta}) {
                for (int k = 0; k < n; k++) {
                    a[k] = real();
                }
            }
            if (covariance) {
                for (int i = 0; i < r.cov.length; i++) {
                    r.cov[i] = real();
                }
            }
            double x = real();
            double y = real();
            double theta = real();
            r.setInitialEstimate(x, y, theta);
            r.durationNs = word();
            if (r.durationNs < 0) {
                throw fail("negative duration " + r.durationNs);
            }
            long[] peaks = use.peakBytes;
            for (int a = 0; a < MissionSizes.AREA_COUNT; a++) {
                peaks[a] = word();
                if (peaks[a] < -1) {
                    throw fail("area " + MissionSizes.AREA_NAMES[a] + " used " + peaks[a] + " bytes");
                }
            }
            section = word();
            if (section != MissionRunFile.RELEASE_SECTION) {
                throw fail("word " + Long.toHexString(section) + " where the release section's code belongs");
            }
            for (int a = MissionSizes.PREDICT; a < MissionSizes.AREA_COUNT; a++) {
                use.releases[a] = word();
                use.allocatingReleases[a] = word();
                use.allocatedBytes[a] = word();
                if (!agree(peaks[a], use.releases[a], use.allocatingReleases[a], use.allocatedBytes[a])) {
                    throw fail("area " + MissionSizes.AREA_NAMES[a] + ": " + use.releases[a] + " releases, "
                            + use.allocatingReleases[a] + " of them allocating " + use.allocatedBytes[a]
                            + " bytes, the largest " + peaks[a] + " bytes: these do not agree");
                }
            }
        } catch (EOFException e) {
            throw fail("truncated");
        }
        if (in.read() >= 0) {
            throw fail("bytes after the end of the records");
        }
        return r;
    }

    /**
     * Whether a private memory's counts can come from one run: none negative, the allocating releases
     * among the releases, bytes only from allocating releases, each of them between 1 byte and the
     * largest release.
     */
    static boolean agree(long largest, long releases, long allocating, long bytes) {
        if (largest < 0 || releases < 0 || allocating < 0 || allocating > releases || bytes < 0) {
            return false;
        }
        if (allocating == 0) {
            return bytes == 0 && largest == 0;
        }
        // allocating <= bytes <= allocating * largest, without overflowing the product
        return largest > 0 && bytes >= allocating && bytes / allocating + (bytes % allocating == 0 ? 0 : 1) <= largest;
    }

    private long time(int k) throws IOException, RunFailure {
        long t = word();
        if (t < -1) {
            throw fail("event " + k + ": time " + t + " (ns are >= 0, -1 for none)");
        }
        return t;
    }

    /** The outcome of event k: a code of an ended job; a completed job has a start and ends after it. */
    private byte outcome(int k, JobRecords r) throws IOException, RunFailure {
        long o = word();
        if (o == JobRecords.PENDING) {
            throw fail("event " + k + " never ended on the HVM (the mission terminated early)");
        }
        if (o != JobRecords.DONE && o != JobRecords.LATE && o != JobRecords.SKIPPED && o != JobRecords.TERMINATED) {
            throw fail("event " + k + ": outcome " + o + " is not a code of an ended job");
        }
        if ((o == JobRecords.DONE || o == JobRecords.LATE) && (r.startNs[k] < 0 || r.endNs[k] < r.startNs[k])) {
            throw fail("event " + k + ": completed, but its start " + r.startNs[k] + " and end " + r.endNs[k] + " disagree");
        }
        return (byte) o;
    }

    private long word() throws IOException {
        return Long.reverseBytes(in.readLong());
    }

    private double real() throws IOException {
        return Double.longBitsToDouble(word());
    }

    private RunFailure fail(String problem) {
        return new RunFailure("the HVM's result file " + name + ": " + problem);
    }
}
