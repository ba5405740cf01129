package org.jmclbench.verification.mission;

import org.jmclbench.core.mcl.DelegatingLocalizer;
import org.jmclbench.core.mcl.Localizer;
import org.jmclbench.core.mcl.MclConfig;
import org.jmclbench.core.mcl.Playground;
import org.jmclbench.scj.ImmortalEntry;
import org.jmclbench.scj.JobGate;
import org.jmclbench.scj.MissionConfiguration;
import org.jmclbench.core.policy.OverrunPolicy;
import org.jmclbench.scj.Robot;

/**
 * The mission's configuration with the checks around its robot ({@link CheckedRobot}, P3 and P4),
 * through the factories the mission offers, and a seeded fault's parts in place of the shipped
 * ones. A fault is either a {@link DelegatingLocalizer} subclass with a public constructor taking
 * the shipped localizer (a faulty job: made in mission memory around the shipped localizer, where
 * the mission makes its localizer) or a {@link MissionFault} with a public no-argument
 * constructor. Keeps the robot and the gate it made, for the driver's checks after the mission.
 */
public final class CheckedConfiguration extends MissionConfiguration {
    private final Class<?> faultClass;
    private final MissionFault fault;
    private CheckedRobot robot;
    private JobGate gate;
    private HorizonTimeSource clock;
    private long jobCostNs;

    /** {@code fault}: a seeded fault's class, or null for the shipped mission. */
    public CheckedConfiguration(MclConfig mcl, OverrunPolicy policy, Class<?> fault)
            throws ReflectiveOperationException {
        super(mcl, policy, 1.0);
        this.faultClass = fault;
        this.fault = fault != null && MissionFault.class.isAssignableFrom(fault)
                ? (MissionFault) fault.getDeclaredConstructor().newInstance() : new MissionFault.None();
    }

    @Override
    public Localizer newLocalizer(Playground playground, double startX, double startY, double startTheta) {
        Localizer shipped = shipped(playground, startX, startY, startTheta);
        if (faultClass == null || !DelegatingLocalizer.class.isAssignableFrom(faultClass)) {
            return fault.localizer(shipped);
        }
        try {
            return (Localizer) faultClass.getConstructor(Localizer.class).newInstance(shipped);
        } catch (ReflectiveOperationException e) {
            throw new IllegalArgumentException(faultClass + " needs a public constructor taking a Localizer", e);
        }
    }

    /** The shipped localizer of the configured memory style (the oracle's, too). */
    Localizer shipped(Playground playground, double startX, double startY, double startTheta) {
        return super.newLocalizer(playground, startX, startY, startTheta);
    }

    @Override
    public Robot newRobot(Localizer localizer, ImmortalEntry entry) {
        CheckedRobot r = fault.robot(localizer, entry);
        robot = r != null ? r : new CheckedRobot(localizer, entry);
        robot.expectPolls(mcl.pollInterval);
        robot.executesIn(clock, jobCostNs);
        return robot;
    }

    @Override
    public JobGate newGate(int events) {
        JobGate g = fault.gate(this, events);
        gate = g != null ? g : super.newGate(events);
        return gate;
    }

    /** Each job of the mission takes {@code costNs} of {@code clock}'s virtual time (before the mission starts). */
    void jobsTake(HorizonTimeSource clock, long costNs) {
        this.clock = clock;
        this.jobCostNs = costNs;
    }

    /** The robot the mission got. */
    CheckedRobot robot() {
        return robot;
    }

    /** The gate the mission got. */
    JobGate gate() {
        return gate;
    }
}
