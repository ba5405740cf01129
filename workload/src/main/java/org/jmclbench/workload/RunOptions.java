package org.jmclbench.workload;

import java.util.Locale;

import org.jmclbench.core.mcl.MclConfig;
import org.jmclbench.core.policy.OverrunPolicy;

/**
 * Every option of one workload run (docs/FORMATS.md section 2), with the defaults filled in;
 * produced by {@link RunOptionsParser}. Fields are plain data, set only by the parser (and tests).
 */
public final class RunOptions {
    /** The {@code --engine} that runs the jobs (SPEC sections 4 and 12): a name of {@code engine.Engines}. */
    public String engine = "javase";
    /** The rtsj engine's design (issue 19). */
    public org.jmclbench.workload.rtsj.RtsjDesign rtsjDesign = org.jmclbench.workload.rtsj.RtsjDesign.THESIS;
    /**
     * The runtime name of the run path when {@code -j} is not given: the engine's, set by the
     * parser ({@code engine.Engine#runtimeName}); null = the running JVM's.
     */
    public String engineRuntimeName;
    /**
     * Memory area sizes set with {@code --area-size AREA=BYTES} (scj and hvm engines), in the order given;
     * empty = every area sized from the workload.
     */
    public final java.util.Map<String, Long> areaSizes = new java.util.LinkedHashMap<>();
    public int particles = 400;
    /** The number of the test: the last folder of the run path. */
    public int number = 1;
    /** Runtime name in the output path; null = derived from the running JVM ({@link #defaultRuntimeName()}). */
    public String runtimeName;
    public String out = "results";
    /** Thesis-format files (all three, or none). */
    public String odo;
    public String laser;
    public String real;
    /** A dataset folder; null = the default. Exclusive with odo/laser/real. */
    public String dataset;
    public OverrunPolicy policy = OverrunPolicy.SKIP;
    public boolean ideal;
    public boolean covariance;
    public MclConfig.Memory memory = MclConfig.Memory.PREALLOCATED;
    public MclConfig.Estimate estimate = MclConfig.Estimate.MEAN;
    public MclConfig.Resample resample = MclConfig.Resample.SYSTEMATIC;
    public MclConfig.Init init = MclConfig.Init.KNOWN;
    public long seed = 1;
    /** Multiplies every event time and deadline: 0.5 replays twice as fast. */
    public double timeScale = 1.0;
    /**
     * The time scales a run accepts: below, the predict deadline (50 ms) rounds to its release;
     * above, an hour of data no longer fits the nanosecond clock's range once scaled.
     */
    public static final double TIME_SCALE_MIN = 1e-6;
    public static final double TIME_SCALE_MAX = 1e3;
    /** Seconds of data replayed first and discarded. */
    public double warmupS = 0.0;
    /** Park until this many microseconds before each release, then spin. */
    public long spinUs = 0;
    public boolean gcLog;
    /**
     * Whether each job's thread CPU time is measured (the cpu_ns column); {@code --no-cpu-time}
     * clears it, saving the two clock reads per job (system calls on a VM, docs/RELEASE-ENGINE.md).
     */
    public boolean cpuTime = true;
    /** Background allocation load in MB/s ({@code --load-alloc}); 0 = none. */
    public int loadAllocMbPerS;
    /** Live set of the background allocation load in MB. */
    public int loadAllocLiveMb;
    /** The load scenario the run was started under, recorded in summary.json ({@code --load-name}). */
    public String loadName;
    public boolean force;
    public boolean help;

    /** The filter configuration these options select. */
    public MclConfig mclConfig() {
        return MclConfig.builder().particles(particles).estimate(estimate).resample(resample).init(init)
                .memory(memory).seed(seed).covariance(covariance).build();
    }

    /** The load scenario recorded with the run: {@code --load-name}, else {@code alloc} or {@code none}. */
    public String effectiveLoadName() {
        return loadName != null ? loadName : loadAllocMbPerS > 0 ? "alloc" : "none";
    }

    /** The runtime name used in the output path: the option, else the engine's, else the running JVM's. */
    public String effectiveRuntimeName() {
        if (runtimeName != null) {
            return runtimeName;
        }
        return engineRuntimeName != null ? engineRuntimeName : defaultRuntimeName();
    }

    /** The test folder: IdealTest for ideal runs, else the policy's (SkipTest, TermTest, QueueTest). */
    public String testFolder() {
        return ideal ? "IdealTest" : policy.folder;
    }

    /** {@code java.vendor}-{@code java.specification.version} in lower case, made a safe path component. */
    public static String defaultRuntimeName() {
        String raw = System.getProperty("java.vendor", "java") + "-" + System.getProperty("java.specification.version", "");
        String s = raw.toLowerCase(Locale.ROOT).replaceAll("[^a-z0-9._+-]+", "-").replaceAll("-+", "-");
        s = s.replaceAll("^[-.]+", "").replaceAll("-+$", "");
        return s.isEmpty() ? "java" : s;
    }

    /** A lower-case label of an enum constant, as written in options and summary.json. */
    public static String label(Enum<?> e) {
        return e.name().toLowerCase(Locale.ROOT);
    }
}
