package org.jmclbench.scj;

import org.jmclbench.core.mcl.MclConfig;

/**
 * The run file and the result file by which a launcher hands an SCJ VM's mission its input and
 * takes back its records (docs/HVM.md): the one definition of their word positions, magic
 * numbers and codes, used by the writing and the reading side alike. Every word is a 64-bit
 * little-endian integer; a double travels as its raw IEEE 754 bits. Enumerations travel as the
 * explicit codes below, never as ordinals, so that reordering a Java enum cannot change the file.
 */
public final class MissionRunFile {
    /** "JMCLHVI1" and "JMCLHVO1" read as little-endian longs. */
    public static final long INPUT_MAGIC = 0x314956484C434D4AL;
    public static final long OUTPUT_MAGIC = 0x314F56484C434D4AL;
    /**
     * The layout's version, in both files; a change of layout changes it (2: the result file's abort
     * section; 3: when each job saw its abort request, in that section; 4: the private memories'
     * use, the largest release among the areas' uses and the releases in their own section).
     */
    public static final long VERSION = 4;
    /**
     * The result file's code ("ABORTNS" read as a little-endian long) that opens its abort section:
     * each event's abort request (JobRecords.abortNs), then when its job saw it (JobRecords.abortSeenNs),
     * after the outcomes.
     */
    public static final long ABORT_SECTION = 0x00534E54524F4241L;
    /**
     * The result file's code ("RELEASES" read as a little-endian long) that opens its last section,
     * after the areas' uses: for each handler's private memory (from {@link MissionSizes#PREDICT} on),
     * its releases, how many of them allocated, and the bytes they allocated in all.
     */
    public static final long RELEASE_SECTION = 0x53455341454C4552L;

    // The run file's header, by word: the filter, the policy (OverrunPolicy.code), the time scale.
    public static final int MAGIC_WORD = 0;
    public static final int VERSION_WORD = 1;
    public static final int PARTICLES = 2;
    public static final int ESTIMATE = 3;
    public static final int RESAMPLE = 4;
    public static final int INIT = 5;
    public static final int MEMORY = 6;
    public static final int SEED = 7;
    public static final int COVARIANCE = 8;
    public static final int POLL_INTERVAL = 9;
    public static final int POLICY = 10;
    public static final int TIME_SCALE = 11;
    /** The area sizes set with --area-size (0 = computed), in the order of {@link MissionSizes#AREA_NAMES}. */
    public static final int AREA_SIZES = 12;
    /**
     * Where the dataset starts: odometry count, laser count, field width and height, beacon
     * count, the beacons' x then y, the start pose, then the columns odometry time, dx, dy,
     * dtheta, laser time, angle.
     */
    public static final int DATA = AREA_SIZES + MissionSizes.AREA_COUNT;

    /**
     * What icecap's own Level 1 infrastructure places in immortal memory besides the mission's
     * data (its scheduler's queues, the processes and their stacks), in bytes.
     */
    public static final long IMMORTAL_INFRASTRUCTURE = 1024 * 1024;
    /** The stacks of the mission's three handlers (int[STACK_WORDS] each), in bytes: icecap puts them in mission memory. */
    public static final long HANDLER_STACKS = 3 * (4 * MissionSizes.STACK_WORDS + 64);

    /** The backing store of icecap's idle task, in bytes: the executable sets icecap's Const.IDLE_BACKING_STORE to it. */
    public static final long IDLE_BACKING_STORE = 2 * 1000;
    /** Room for the bookkeeping of nested backing stores, in bytes. */
    public static final long NESTING_SLACK = 256 * 1024;

    private MissionRunFile() {
    }

    /** The sizes icecap is given for every area ({@link #icecapSize}), by area index. */
    public static long[] icecapSizes(MissionConfiguration config, MissionSizes sizes) {
        long[] icecap = new long[MissionSizes.AREA_COUNT];
        for (int a = 0; a < icecap.length; a++) {
            icecap[a] = icecapSize(config, sizes, a);
        }
        return icecap;
    }

    /**
     * The overall backing store icecap takes from the HVM's heap for areas of these sizes
     * ({@link #icecapSizes}): icecap nests the areas, the mission memory inside the sequencer's
     * private memory (each of the mission's size), the handlers' private memories and their
     * backing stores inside the mission memory's reservation; beside them immortal memory and
     * the idle task's store. Generous, so that the nesting fits; each area is still limited to its
     * own size. A long: sizes set with --area-size may add up past an int.
     */
    public static long overallBackingStore(long[] icecapSizes) {
        long mission = icecapSizes[MissionSizes.MISSION];
        long handlers = icecapSizes[MissionSizes.PREDICT] + icecapSizes[MissionSizes.UPDATE]
                + icecapSizes[MissionSizes.SENSOR];
        return icecapSizes[MissionSizes.IMMORTAL] + 2 * (mission + mission + handlers) + NESTING_SLACK
                + IDLE_BACKING_STORE;
    }

    /**
     * The size icecap is given for {@code area}: the mission's ({@code sizes}), plus icecap's own
     * room ({@link #IMMORTAL_INFRASTRUCTURE} in immortal, {@link #HANDLER_STACKS} in mission memory)
     * when the size is computed; a size set in {@code config} (--area-size) is taken as it is.
     */
    public static long icecapSize(MissionConfiguration config, MissionSizes sizes, int area) {
        long room = 0;
        if (config.areaSize(area) == 0) {
            room = area == MissionSizes.IMMORTAL ? IMMORTAL_INFRASTRUCTURE : area == MissionSizes.MISSION ? HANDLER_STACKS : 0;
        }
        return sizes.size(area) + room;
    }

    /** The code of an estimate choice: mean 0, best 1. */
    public static long code(MclConfig.Estimate e) {
        return e == MclConfig.Estimate.MEAN ? 0 : 1;
    }

    /** The code of a resampling choice: systematic 0, multinomial 1. */
    public static long code(MclConfig.Resample r) {
        return r == MclConfig.Resample.SYSTEMATIC ? 0 : 1;
    }

    /** The code of an initialisation: known 0, uniform 1. */
    public static long code(MclConfig.Init i) {
        return i == MclConfig.Init.KNOWN ? 0 : 1;
    }

    /** The code of a memory style: preallocated 0, scoped 2 (allocating, 1, is no style of the mission). */
    public static long code(MclConfig.Memory m) {
        return m == MclConfig.Memory.PREALLOCATED ? 0 : m == MclConfig.Memory.ALLOCATING ? 1 : 2;
    }

    /** The estimate choice of a code, or null. */
    public static MclConfig.Estimate estimate(long code) {
        return code == 0 ? MclConfig.Estimate.MEAN : code == 1 ? MclConfig.Estimate.BEST : null;
    }

    /** The resampling choice of a code, or null. */
    public static MclConfig.Resample resample(long code) {
        return code == 0 ? MclConfig.Resample.SYSTEMATIC : code == 1 ? MclConfig.Resample.MULTINOMIAL : null;
    }

    /** The initialisation of a code, or null. */
    public static MclConfig.Init init(long code) {
        return code == 0 ? MclConfig.Init.KNOWN : code == 1 ? MclConfig.Init.UNIFORM : null;
    }

    /** The memory style of a code, or null. */
    public static MclConfig.Memory memory(long code) {
        return code == 0 ? MclConfig.Memory.PREALLOCATED : code == 1 ? MclConfig.Memory.ALLOCATING
                : code == 2 ? MclConfig.Memory.SCOPED : null;
    }
}
