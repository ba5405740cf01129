package org.jmclbench.hvm.launcher;

import java.util.Locale;

import org.jmclbench.core.mcl.MclConfig;

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

    private HvmLimits() {
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
