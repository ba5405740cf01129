package org.jmclbench.scj;

import javax.realtime.ConfigurationParameters;
import javax.realtime.PriorityParameters;
import javax.realtime.memory.ScopeParameters;
import javax.safetycritical.LinearMissionSequencer;
import javax.safetycritical.MissionSequencer;
import javax.safetycritical.PriorityScheduler;
import javax.safetycritical.Safelet;

/**
 * The application: a Safelet whose LinearMissionSequencer runs the {@link MclMission} once. It is
 * built by the platform's launcher code (on Java SE the workload, on an SCJ VM its main) from a
 * {@link MissionConfiguration}, a {@link MissionInput} and a {@link MissionOutput}; the memory
 * sizes it announces come from {@link MissionSizes}.
 */
public class MclSafelet implements Safelet {
    private final MissionConfiguration configuration;
    private final MissionInput input;
    private final MissionOutput output;
    private final MissionSizes sizes;
    private ImmortalEntry entry;
    private MclMission mission;

    public MclSafelet(MissionConfiguration configuration, MissionInput input, MissionOutput output) {
        this.configuration = configuration;
        this.input = input;
        this.output = output;
        this.sizes = new MissionSizes(configuration, input.odometryCount(), input.laserCount());
    }

    @Override
    public void initializeApplication(String[] args) {
        // Runs in immortal memory: the sensor log, the schedule and the records live here for good.
        entry = new ImmortalEntry(input, configuration);
    }

    @Override
    public MissionSequencer getSequencer() {
        int norm = PriorityScheduler.instance().getNormPriority();
        mission = new MclMission(this);
        return new LinearMissionSequencer(new PriorityParameters(norm),
                new ScopeParameters(sizes.size(MissionSizes.MISSION), 0, 0, sizes.backingStore()),
                new ConfigurationParameters(-1, -1, new long[] {MissionSizes.STACK_WORDS}),
                mission, false, "mcl");
    }

    @Override
    public long immortalMemorySize() {
        return sizes.size(MissionSizes.IMMORTAL);
    }

    @Override
    public long managedMemoryBackingStoreSize() {
        return sizes.backingStore();
    }

    @Override
    public boolean handleStartupError(int cause, long value) {
        return false;
    }

    @Override
    public void cleanUp() {
    }

    /** The immortal state; null before {@code initializeApplication}. */
    public ImmortalEntry entry() {
        return entry;
    }

    /** The mission, once the sequencer has been asked for (for tests, after the run). */
    public MclMission mission() {
        return mission;
    }

    /** The run's configuration. */
    public MissionConfiguration configuration() {
        return configuration;
    }

    /** The memory sizes announced to the platform. */
    public MissionSizes sizes() {
        return sizes;
    }

    MissionOutput output() {
        return output;
    }
}
