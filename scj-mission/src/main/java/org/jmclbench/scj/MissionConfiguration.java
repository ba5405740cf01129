package org.jmclbench.scj;

import org.jmclbench.core.mcl.Localizer;
import org.jmclbench.core.mcl.MclConfig;
import org.jmclbench.core.mcl.Playground;
import org.jmclbench.core.mcl.PreallocatedLocalizer;
import org.jmclbench.core.mcl.ScopedLocalizer;
import org.jmclbench.core.policy.OverrunPolicy;

/**
 * Everything a run of the mission is parameterised by, and the factory of the parts a test may
 * replace. The seams (for verification's seeded bugs): override {@link #newLocalizer},
 * {@link #newRobot} or {@link #newGate} in a subclass and hand it to {@link MclSafelet}. The
 * sizes are all small-able: particles and the poll interval through {@link MclConfig}, the
 * events through the {@link MissionInput}. Nothing here is static, so two missions in one
 * process never share state.
 */
public class MissionConfiguration {
    /** The filter: particles, estimate, resampling, initialisation, seed, covariance, poll interval and memory style. */
    public final MclConfig mcl;
    /** What an event released while the robot is busy does. */
    public final OverrunPolicy policy;
    /** Multiplies every event time and deadline: 0.5 replays twice as fast. */
    public final double timeScale;
    // Area sizes set explicitly (bytes), by MissionSizes area index; 0 = computed from the workload.
    private final long[] areaSizes = new long[MissionSizes.AREA_COUNT];

    /**
     * @param mcl the filter; its memory style must be {@code preallocated} or {@code scoped}
     * @param timeScale positive; 1 replays in real time
     */
    public MissionConfiguration(MclConfig mcl, OverrunPolicy policy, double timeScale) {
        if (mcl.memory != MclConfig.Memory.PREALLOCATED && mcl.memory != MclConfig.Memory.SCOPED) {
            throw new IllegalArgumentException("the SCJ mission has the preallocated and scoped memory styles only");
        }
        if (!(timeScale > 0) || Double.isInfinite(timeScale)) {
            throw new IllegalArgumentException("time scale must be positive and finite");
        }
        this.mcl = mcl;
        this.policy = policy;
        this.timeScale = timeScale;
    }

    /** Sets the size (bytes, positive) of one memory area, overriding the computed size; see {@link MissionSizes#AREA_NAMES}. */
    public MissionConfiguration areaSize(int area, long bytes) {
        if (bytes <= 0) {
            throw new IllegalArgumentException("area size must be positive");
        }
        areaSizes[area] = bytes;
        return this;
    }

    /** The size set for an area, or 0 when it is computed. */
    public long areaSize(int area) {
        return areaSizes[area];
    }

    /** The localizer of the configured memory style; called in mission memory by {@code initialize()}. */
    public Localizer newLocalizer(Playground playground, double startX, double startY, double startTheta) {
        if (mcl.memory == MclConfig.Memory.SCOPED) {
            return new ScopedLocalizer(mcl, playground, startX, startY, startTheta);
        }
        return new PreallocatedLocalizer(mcl, playground, startX, startY, startTheta);
    }

    /** The robot, the one shared resource the jobs work on; called in mission memory. */
    public Robot newRobot(Localizer localizer, ImmortalEntry entry) {
        return new Robot(localizer, entry);
    }

    /** The policy's admission and abort state; called in mission memory. */
    public JobGate newGate(int events) {
        return new JobGate(policy, events);
    }
}
