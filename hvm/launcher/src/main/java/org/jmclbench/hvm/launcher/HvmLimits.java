package org.jmclbench.hvm.launcher;

import java.io.File;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.util.List;
import java.util.Locale;

import org.jmclbench.core.mcl.MclConfig;
import org.jmclbench.scj.MissionRunFile;

/**
 * What the icecap HVM cannot hold, checked before anything is built or started (docs/HVM.md,
 * known limits): its array lengths and {@code System.arraycopy}'s length are 16 bits. Past them
 * the mission does not fail cleanly: 65,536 particles end the executable with an
 * ArrayIndexOutOfBoundsException (exit 139), the scoped style at 8,192 particles copies nothing
 * back and localises wrongly without a word, and with -c a dataset of 10,923 events hangs. Each
 * limit was measured at its boundary (docs/HVM.md).
 */
final class HvmLimits {
    /** The most elements an array holds. */
    static final int MAX_ARRAY_LENGTH = 65_535;
    /** The most bytes one System.arraycopy copies. */
    static final int MAX_COPY_BYTES = 65_535;
    /** The scoped style copies each particle's x, y and theta back, one array of doubles each. */
    static final int MAX_SCOPED_PARTICLES = MAX_COPY_BYTES / Double.BYTES;
    /** The covariance record keeps six values an event. */
    static final int COVARIANCE_VALUES = 6;

    /** Where the executable's heap size is written, under the project home: hvm/build-mission.sh builds with it. */
    static final String HEAP_FILE = "hvm/hvm.properties";
    /**
     * What the executable places in its heap besides the backing store (the run's configuration,
     * the input, the Safelet, icecap's own objects), in bytes, with room to spare: measured
     * between 22,000 and 30,000 bytes whatever the filter (docs/HVM.md, known limits).
     */
    static final long HEAP_RESERVE = 64 * 1024;

    private HvmLimits() {
    }

    /**
     * The executable's heap in bytes, the {@code heap=} line of {@link #HEAP_FILE} under {@code home}
     * read as hvm/build-mission.sh reads it; -1 when there is none to read (no source tree: the build,
     * which needs one, says so) or it is malformed (the script refuses it before building).
     */
    static long heapBytes(File home) {
        List<String> lines;
        try {
            lines = Files.readAllLines(new File(home, HEAP_FILE).toPath(), StandardCharsets.UTF_8);
        } catch (IOException e) {
            return -1;
        }
        String value = null;
        for (String line : lines) {
            if (line.startsWith("heap=")) {
                if (value != null) {
                    return -1;
                }
                value = line.substring("heap=".length());
            }
        }
        return value != null && value.matches("[1-9][0-9]{0,17}") ? Long.parseLong(value) : -1;
    }

    /**
     * Why the HVM cannot hold the backing store of areas of these sizes ({@code icecapSizes}, as
     * icecap is given them) in a heap of {@code heap} bytes, naming --area-size when sizes were
     * set with it; null when it can, or when the heap is not known ({@code heap < 0}). Past it the
     * executable failed at launch with "memory area of 268435456 bytes (an icecap-internal area)
     * overflowed", and icecap's int sizes wrapped.
     */
    static String beyondHeap(long[] icecapSizes, long heap, boolean sizesSet) {
        long store = MissionRunFile.overallBackingStore(icecapSizes);
        long most = Math.min(heap - HEAP_RESERVE, Integer.MAX_VALUE);
        if (heap < 0 || store <= most) {
            return null;
        }
        return String.format(Locale.ROOT, "%s: the SCJ backing store of these areas is %,d bytes, more than the"
                + " HVM's heap holds (%,d bytes of its %,d, %s; docs/HVM.md)", sizesSet ? "--area-size" : "the computed"
                + " area sizes", store, most, heap, HEAP_FILE);
    }

    /**
     * Why the HVM cannot run the mission with this filter on a dataset of {@code events} events
     * (odometry and laser), naming the option; null when it can.
     */
    static String beyond(MclConfig mcl, int events) {
        if (mcl.memory == MclConfig.Memory.SCOPED && mcl.particles > MAX_SCOPED_PARTICLES) {
            return String.format(Locale.ROOT, "--particles %d: the HVM runs the scoped memory style with at most %,d"
                    + " particles (System.arraycopy copies at most %,d bytes there; docs/HVM.md)", mcl.particles,
                    MAX_SCOPED_PARTICLES, MAX_COPY_BYTES);
        }
        if (mcl.particles > MAX_ARRAY_LENGTH) {
            return String.format(Locale.ROOT, "--particles %d: the HVM holds at most %,d particles (its arrays hold at"
                    + " most %,d elements; docs/HVM.md)", mcl.particles, MAX_ARRAY_LENGTH, MAX_ARRAY_LENGTH);
        }
        if (events > MAX_ARRAY_LENGTH) {
            return String.format(Locale.ROOT, "the dataset's %,d events are more than the HVM's arrays hold (%,d"
                    + " elements; docs/HVM.md)", events, MAX_ARRAY_LENGTH);
        }
        if (mcl.covariance && (long) COVARIANCE_VALUES * events > MAX_ARRAY_LENGTH) {
            return String.format(Locale.ROOT, "-c: the covariance of the dataset's %,d events is %d values an event,"
                    + " more than the HVM's arrays hold (%,d elements: at most %,d events; docs/HVM.md)", events,
                    COVARIANCE_VALUES, MAX_ARRAY_LENGTH, MAX_ARRAY_LENGTH / COVARIANCE_VALUES);
        }
        return null;
    }
}
