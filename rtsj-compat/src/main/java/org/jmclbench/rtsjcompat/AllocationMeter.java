package org.jmclbench.rtsjcompat;

/**
 * The allocation seam: how many bytes the calling thread has allocated so far. The memory
 * areas are charged with differences of these readings.
 *
 * <p>{@code -Djmclbench.scj.meter=auto} (the default) uses the JVM's per-thread allocation
 * counter ({@code com.sun.management.ThreadMXBean}, HotSpot and OpenJ9) where it exists and
 * {@link #NONE} elsewhere; {@code none} forces {@link #NONE} (Java PathFinder, whose
 * listener sees allocations itself).
 */
public abstract class AllocationMeter {
    /** The system property that selects the meter: {@code auto} or {@code none}. */
    public static final String PROPERTY = "jmclbench.scj.meter";

    /** Measures nothing: every reading is 0, and {@link #measures()} is false. */
    public static final AllocationMeter NONE = new AllocationMeter() {
        @Override
        public long allocatedBytes() {
            return 0;
        }

        @Override
        public boolean measures() {
            return false;
        }

        @Override
        public String name() {
            return "none";
        }
    };

    private static final Installed<AllocationMeter> CURRENT = new Installed<AllocationMeter>() {
        @Override
        AllocationMeter choose() {
            return fromProperty(System.getProperty(PROPERTY, "auto"));
        }
    };

    /** The installed meter (chosen from {@link #PROPERTY} at first use). */
    public static AllocationMeter current() {
        return CURRENT.get();
    }

    /** Installs a meter (tests, verification); call it before a launch, not during one. */
    public static void install(AllocationMeter meter) {
        CURRENT.install(meter, "meter");
    }

    static AllocationMeter fromProperty(String value) {
        if ("none".equals(value)) {
            return NONE;
        }
        if (!"auto".equals(value)) {
            throw new IllegalArgumentException("-D" + PROPERTY + " must be auto or none, not " + value);
        }
        try {
            // Loaded by name so that this jar still loads where com.sun.management is missing.
            Class<?> c = Class.forName("org.jmclbench.rtsjcompat.ThreadMxAllocationMeter");
            AllocationMeter m = (AllocationMeter) c.getDeclaredConstructor().newInstance();
            return m.measures() ? m : NONE;
        } catch (Exception | LinkageError e) {
            return NONE;
        }
    }

    /** Bytes the calling thread has allocated since it started (0 when not measured). */
    public abstract long allocatedBytes();

    /**
     * Bytes one call of {@link #allocatedBytes()} itself adds to the next reading; the
     * accounting subtracts it from every difference.
     */
    public long selfCost() {
        return 0;
    }

    /** Whether readings are real. */
    public abstract boolean measures();

    /** A short name for reports. */
    public abstract String name();
}
