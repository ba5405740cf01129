package org.jmclbench.scj;

import javax.realtime.AbsoluteTime;
import javax.realtime.AperiodicParameters;
import javax.realtime.ConfigurationParameters;
import javax.realtime.PeriodicParameters;
import javax.realtime.PriorityParameters;
import javax.realtime.RelativeTime;
import javax.realtime.memory.ScopeParameters;
import javax.safetycritical.Mission;
import javax.safetycritical.PriorityScheduler;

import org.jmclbench.core.mcl.Localizer;
import org.jmclbench.core.record.JobRecords;

/**
 * The MCL mission. {@code initialize()} builds, in mission memory, the localizer (the particles),
 * the robot, the policy's gate and the three handlers: the periodic predict handler, the
 * aperiodic update handler and the laser sensor (a one-shot handler) that releases it. The
 * mission ends when every event has ended; its cleanup hands the records to the output.
 */
public class MclMission extends Mission {
    private final MclSafelet safelet;
    private final MissionClock clock = new MissionClock();
    // This object lives as long as the Safelet (immortal memory, built before the sequencer
    // runs), so it keeps no reference to the robot, the gate or the handlers (mission memory):
    // an SCJ VM raises IllegalAssignmentError at such a store. A count is a primitive copy.
    private volatile int endedEvents;

    MclMission(MclSafelet safelet) {
        this.safelet = safelet;
    }

    @Override
    protected void initialize() {
        ImmortalEntry entry = safelet.entry();
        MissionConfiguration config = safelet.configuration();
        MissionSizes sizes = safelet.sizes();
        JobRecords records = entry.records;
        records.clear();
        Localizer localizer = config.newLocalizer(entry.playground, entry.startX, entry.startY, entry.startTheta);
        records.setInitialEstimate(localizer.estimateX(), localizer.estimateY(), localizer.estimateTheta());
        Robot robot = config.newRobot(localizer, entry);
        JobGate gate = config.newGate(entry.size());
        MissionOutput output = safelet.output();
        gate.recordAbortsIn(records);
        gate.orderTies(entry.timeline, entry.releaseNs);

        // The sensor stands for an interrupt: above the two tasks, which share one priority.
        int top = PriorityScheduler.instance().getMaxPriority();
        PriorityParameters taskPriority = new PriorityParameters(top - 1);
        PriorityParameters sensorPriority = new PriorityParameters(top);
        ConfigurationParameters stack = new ConfigurationParameters(-1, -1, new long[] {MissionSizes.STACK_WORDS});

        long firstOdo = entry.releaseNs[entry.odoEvent[0]];
        RelativeTime period = relative(entry.periodNs);
        PredictHandler predict = new PredictHandler(taskPriority,
                new PeriodicParameters(relative(firstOdo), period, period, null),
                privateMemory(sizes.size(MissionSizes.PREDICT)), stack, entry, gate,
                new JobRunner(robot, gate, entry, clock, this, output, MissionSizes.PREDICT));
        predict.register();
        if (entry.laserEvent.length > 0) {
            ReleaseQueue queue = new ReleaseQueue(entry.laserEvent.length);
            UpdateHandler update = new UpdateHandler(taskPriority, new AperiodicParameters(),
                    privateMemory(sizes.size(MissionSizes.UPDATE)), stack, queue,
                    new JobRunner(robot, gate, entry, clock, this, output, MissionSizes.UPDATE));
            update.register();
            LaserSensor sensor = new LaserSensor(sensorPriority, relative(entry.releaseNs[entry.laserEvent[0]]),
                    new AperiodicParameters(), privateMemory(sizes.size(MissionSizes.SENSOR)), stack, entry, gate,
                    queue, update, new JobRunner(robot, gate, entry, clock, this, output, MissionSizes.SENSOR), clock);
            sensor.register();
        }
        // Last: the handlers' relative start times count from here.
        clock.start(new AbsoluteTime());
    }

    @Override
    public long missionMemorySize() {
        return safelet.sizes().size(MissionSizes.MISSION);
    }

    @Override
    protected boolean cleanUp() {
        JobRecords records = safelet.entry().records;
        records.durationNs = clock.nowNs(new AbsoluteTime());
        safelet.output().missionEnded(records);
        return super.cleanUp();
    }

    /** Called by the job that ended the last event: records the gate's count and ends the mission. */
    void allEventsEnded(int ended) {
        endedEvents = ended;
        requestTermination();
    }

    /** How many events the gate had counted as ended when the mission was asked to end (for tests). */
    public int endedEvents() {
        return endedEvents;
    }

    private static ScopeParameters privateMemory(long bytes) {
        return new ScopeParameters(bytes, 0, 0, bytes);
    }

    private static RelativeTime relative(long ns) {
        return new RelativeTime(ns / 1000000L, (int) (ns % 1000000L));
    }
}
