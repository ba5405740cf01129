package org.jmclbench.scj;

import org.jmclbench.core.mcl.MclConfig;
import org.jmclbench.core.mcl.ScopedLocalizer;

/**
 * The size of every memory area of the mission, computed from the workload (particles N,
 * odometry events O, laser events L, merged events E = O + L) with the arithmetic written down,
 * in bytes on a 64-bit JVM with compressed references (array header 16 bytes, object header 12,
 * everything padded to 8). Each size is what the area's contents need plus a stated slack for
 * the SCJ infrastructure's own objects (handler parameters, times, the platform's bookkeeping);
 * the compat layer's measured peaks check them (docs in scj-mission/README.md).
 */
public final class MissionSizes {
    /** Area indices, in the order of {@link #AREA_NAMES}. */
    public static final int IMMORTAL = 0;
    public static final int MISSION = 1;
    public static final int PREDICT = 2;
    public static final int UPDATE = 3;
    public static final int SENSOR = 4;
    public static final int AREA_COUNT = 5;
    /** The names of the areas as options and reports spell them; a handler's private memory carries the handler's name. */
    public static final String[] AREA_NAMES = {"immortal", "mission", "predict", "update", "sensor"};

    /** Immortal slack: the Safelet's and sequencer's objects, playground, configuration (16 KiB). */
    public static final long IMMORTAL_SLACK = 16 * 1024;
    /** Mission slack: handlers, their release/scope/priority parameters and the platform's per-handler objects (64 KiB). */
    public static final long MISSION_SLACK = 64 * 1024;
    /** A release's slack: what the platform itself may allocate in a handler's private memory (4 KiB). */
    public static final long RELEASE_SLACK = 4 * 1024;
    /** Stack size handed to each handler's ConfigurationParameters (an SCJ VM's unit: 32-bit words). */
    public static final long STACK_WORDS = 16 * 1024;

    private final long[] sizes = new long[AREA_COUNT];

    /** The sizes for a configuration and a workload of odometry and laser events; explicit sizes in config win. */
    public MissionSizes(MissionConfiguration config, int odometry, int laser) {
        MclConfig m = config.mcl;
        sizes[IMMORTAL] = immortal(m.particles, odometry, laser, m.covariance);
        sizes[MISSION] = mission(m, laser);
        sizes[PREDICT] = RELEASE_SLACK
                + (m.memory == MclConfig.Memory.SCOPED ? ScopedLocalizer.predictTemporaryBytes(m.particles) : 0);
        sizes[UPDATE] = RELEASE_SLACK
                + (m.memory == MclConfig.Memory.SCOPED ? ScopedLocalizer.updateTemporaryBytes(m.particles, m.resample) : 0);
        sizes[SENSOR] = RELEASE_SLACK;
        for (int a = 0; a < AREA_COUNT; a++) {
            if (config.areaSize(a) > 0) {
                sizes[a] = config.areaSize(a);
            }
        }
    }

    /**
     * Immortal memory: the sensor log and everything indexed by event.
     * <pre>
     *   odometry  4 double[O]                  32 O + 4 * 16
     *   laser     2 double[L]                  16 L + 2 * 16
     *   timeline  double[E] byte[E] int[E]     13 E + 3 * 16 + 8 (padding)
     *   schedule  2 long[E]                    16 E + 2 * 16
     *   event map int[O] int[L]                 4 E + 2 * 16
     *   records   8 long[E] byte[E] 3 double[E] 89 E + 12 * 16 + 8
     *             covariance double[6E] (-c)   48 E + 16
     * </pre>
     * plus {@link #IMMORTAL_SLACK}. The particle count does not appear: particles live in mission memory.
     */
    static long immortal(int particles, int odometry, int laser, boolean covariance) {
        long e = (long) odometry + laser;
        long bytes = 32L * odometry + 16L * laser + 13 * e + 16 * e + 4 * e + 89 * e + 25 * 16 + 16;
        if (covariance) {
            bytes += 48 * e + 16;
        }
        return bytes + IMMORTAL_SLACK;
    }

    /**
     * Mission memory: the localizer's particles and the mission's own objects.
     * <pre>
     *   preallocated  6 double[N] (two particle sets) + double[N] weights + int[N] indices
     *                 (+ double[N] multinomial scratch)       56 N + 4 N + 8 * 16 (+ 8 N + 16)
     *   scoped        3 double[N] (the committed set)        24 N + 3 * 16
     *   both          release queue int[L]                    4 L + 16
     * </pre>
     * plus {@link #MISSION_SLACK}.
     */
    static long mission(MclConfig m, int laser) {
        long n = m.particles;
        long bytes;
        if (m.memory == MclConfig.Memory.SCOPED) {
            bytes = 24 * n + 3 * 16;
        } else {
            bytes = 56 * n + (4 * n + 7) / 8 * 8 + 8 * 16;
            if (m.resample == MclConfig.Resample.MULTINOMIAL) {
                bytes += 8 * n + 16;
            }
        }
        return bytes + 4L * laser + 16 + MISSION_SLACK;
    }

    /** The size of an area (bytes). */
    public long size(int area) {
        return sizes[area];
    }

    /** The backing store the mission sequencer needs: mission memory plus every handler's private memory. */
    public long backingStore() {
        return sizes[MISSION] + sizes[PREDICT] + sizes[UPDATE] + sizes[SENSOR];
    }

    /** The area index of a name in {@link #AREA_NAMES}, or -1. */
    public static int areaIndex(String name) {
        for (int a = 0; a < AREA_COUNT; a++) {
            if (AREA_NAMES[a].equals(name)) {
                return a;
            }
        }
        return -1;
    }
}
