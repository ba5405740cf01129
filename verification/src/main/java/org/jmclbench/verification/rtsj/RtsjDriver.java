package org.jmclbench.verification.rtsj;

import org.jmclbench.core.mcl.AbortSignal;
import org.jmclbench.core.mcl.Localizer;
import org.jmclbench.core.mcl.MclConfig;
import org.jmclbench.core.mcl.Playground;
import org.jmclbench.core.policy.OverrunPolicy;
import org.jmclbench.core.record.JobRecords;
import org.jmclbench.core.timeline.Timeline;
import org.jmclbench.rtsjcompat.TimeSource;
import org.jmclbench.verification.Property;
import org.jmclbench.verification.jpf.Coverage;
import org.jmclbench.verification.mission.HorizonTimeSource;
import org.jmclbench.verification.mission.MissionDriver;
import org.jmclbench.verification.mission.PolicyOracle;
import org.jmclbench.verification.mission.PropertyFailure;
import org.jmclbench.workload.RunFailure;
import org.jmclbench.workload.mcl.Localizers;
import org.jmclbench.workload.release.LocalizerJob;
import org.jmclbench.workload.release.ReleaseSchedule;
import org.jmclbench.workload.rtsj.RtsjDesign;
import org.jmclbench.workload.rtsj.RtsjReplay;

/**
 * The rtsj engine's replay ({@link RtsjReplay}: its dispatcher, its bound handlers, their AIEs and
 * the robot's locks, woven with delivery points as the build ships them) on rtsj-compat's RTSJ
 * layer and virtual time, on a tiny synthetic timeline: the program Java PathFinder explores.
 * A job takes {@link MissionDriver#JOB_COST_NS} (5 ms) of virtual time, and the times depend on the
 * design. Thesis: odometry events 2 ms apart, laser events at the last odometry event's instant, so
 * the second odometry release fires at the first predict (deferred: it holds the robot's monitor)
 * and, under terminate, the second predict is superseded by the laser event of its instant before
 * it starts (the rule decides the events of one instant before any of their jobs starts); under
 * queue (one of each) the two share an instant. Atomic: one odometry event at 0, laser events at
 * 2 and 3 ms, so the first laser release interrupts the predict and the second fires at the first
 * update while it waits for the robot's lock (an AIE pending in non-AI code, where no delivery
 * point may be), and the update handler runs a job after an interrupted one. (A second odometry
 * event at 3 ms instead made three jobs contend for the lock: 325,000 states, past the check's
 * budget; the second update waits in its handler, not at the lock.)
 * <ul>
 * <li>P3: {@link CheckedJob} compares the robot before and after every job that did not complete
 * (an AIE unwound it, or it stopped), and after the run the completed jobs, replayed in their
 * commit order on a fresh localizer, must give the recorded estimates and every particle;
 * <li>P5: every event ended once (the replay's count and the records); virtual time has a
 * horizon, so a replay that never ends is a counterexample, not a timeout;
 * <li>P7: an event dropped or aborted only as its policy says ({@link PolicyOracle});
 * <li>P1, P8 and P9 are the listeners' ({@code TimedDeadlockListener}, {@code HeldLockListener},
 * {@code AtcListener}).
 * </ul>
 * A replay that fails without a property failure (a handler's exception, a hang) fails the check
 * as an uncaught error. Usage: {@code RtsjDriver POLICY DESIGN ODOMETRY LASER PARTICLES POLL
 * [LOCALIZER_FAULT]}, where the fault is a {@code DelegatingLocalizer} with a public constructor
 * taking the shipped localizer.
 */
public final class RtsjDriver {
    /** Virtual time after which every event must have ended. */
    static final long HORIZON_NS = 1_000_000_000L;
    /** Between two odometry events (thesis design): less than a job's virtual execution time. */
    static final double THESIS_GAP_S = 0.002;
    /** Between two laser events (atomic design): the second falls while the first update waits for the robot. */
    static final double ATOMIC_LASER_GAP_S = 0.001;
    /** From the odometry event to the first laser event (atomic design): within that predict job. */
    static final double LASER_OFFSET_S = 0.002;
    private static final String[] TASKS = {"predict", "update"};
    private static final String[] OUTCOMES = {"pending", "done", "late", "skipped", "terminated"};

    private RtsjDriver() {
    }

    public static void main(String[] args) throws Exception {
        OverrunPolicy policy = OverrunPolicy.valueOf(args[0].toUpperCase());
        RtsjDesign design = RtsjDesign.of(args[1]);
        int odometry = Integer.parseInt(args[2]);
        int laser = Integer.parseInt(args[3]);
        MclConfig mcl = MclConfig.builder().particles(Integer.parseInt(args[4])).pollInterval(Integer.parseInt(args[5]))
                .build();
        Class<?> fault = args.length > 6 ? Class.forName(args[6]) : null;
        System.setProperty("jmclbench.scj.meter", "none");
        // Non-daemon handler threads: JPF hands over at a thread's end only to a runnable non-daemon.
        System.setProperty("jmclbench.scj.daemon", "false");

        double[] odoTime = new double[odometry];
        double[] laserTime = new double[laser];
        double[] dx = new double[odometry];
        double[] dy = new double[odometry];
        double[] dtheta = new double[odometry];
        double[] angle = new double[laser];
        for (int k = 0; k < odometry; k++) {
            odoTime[k] = THESIS_GAP_S * k;
            dx[k] = 0.01;
            dtheta[k] = 0.01;
        }
        for (int k = 0; k < laser; k++) {
            laserTime[k] = design == RtsjDesign.THESIS ? odoTime[odometry - 1] : LASER_OFFSET_S + ATOMIC_LASER_GAP_S * k;
            angle[k] = 1.0 + 0.5 * k;
        }
        Timeline timeline = Timeline.merge(odoTime, laserTime);
        ReleaseSchedule schedule = ReleaseSchedule.of(timeline, 1.0);
        JobRecords records = new JobRecords(timeline, false);
        Localizer localizer = localizer(mcl, fault);
        // Load the job code's classes before the replay, as the engine's class-loading replay does.
        Localizer warm = localizer(mcl, null);
        warm.predict(0.01, 0.0, 0.01, AbortSignal.NEVER);
        warm.update(1.0, AbortSignal.NEVER);
        CheckedJob job = new CheckedJob(new LocalizerJob(dx, dy, dtheta, angle, timeline, localizer, records),
                localizer, records);
        RtsjReplay replay = new RtsjReplay(schedule, policy, design, job, records);
        HorizonTimeSource clock = new HorizonTimeSource(HORIZON_NS, replay, "ended");
        job.executesIn(clock, MissionDriver.JOB_COST_NS);
        TimeSource.install(clock);
        RunFailure failed = null;
        try {
            replay.run(HORIZON_NS);
        } catch (RunFailure e) {
            failed = e;
        }
        job.rethrow();
        PropertyFailure p5 = new PropertyFailure(Property.P5, "an event did not end exactly once");
        p5.unless(replay.endedCount() == schedule.size(), replay, "ended");
        for (int k = 0; k < records.size(); k++) {
            byte o = records.outcome[k];
            p5.unless(o == JobRecords.DONE || o == JobRecords.LATE || o == JobRecords.SKIPPED
                    || o == JobRecords.TERMINATED, replay, "ended");
        }
        if (failed != null) {
            throw new AssertionError("the rtsj replay failed: " + failed.getMessage(), failed);
        }
        PolicyOracle.check(records, replay, "dispatch", "dispatch");
        job.replayCompleted(localizer(mcl, null), dx, dy, dtheta, angle);
        for (int k = 0; k < records.size(); k++) {
            Coverage.reached(TASKS[timeline.task(k)] + " " + OUTCOMES[records.outcome[k]]);
            if (records.outcome[k] == JobRecords.TERMINATED && records.startNs[k] >= 0) {
                Coverage.reached(TASKS[timeline.task(k)] + " interrupted"); // an AIE cut a running job short
            } else if (replay.abortRequested(k) && records.completed(k)) {
                Coverage.reached(TASKS[timeline.task(k)] + " deferred"); // fired at, and completed: ATC deferred
            }
        }
    }

    private static Localizer localizer(MclConfig mcl, Class<?> fault) throws ReflectiveOperationException {
        Localizer shipped = Localizers.create(mcl, Playground.thesis(), 1.5, 1.0, 0.0);
        return fault == null ? shipped : (Localizer) fault.getConstructor(Localizer.class).newInstance(shipped);
    }
}
