package org.jmclbench.verification.mission;

import org.jmclbench.core.mcl.AbortSignal;
import org.jmclbench.core.mcl.Localizer;
import org.jmclbench.core.mcl.MclConfig;
import org.jmclbench.core.mcl.Playground;
import org.jmclbench.core.record.JobRecords;
import org.jmclbench.core.timeline.Timeline;
import org.jmclbench.rtsjcompat.RunReport;
import org.jmclbench.rtsjcompat.ScjRuntime;
import org.jmclbench.rtsjcompat.TimeSource;
import org.jmclbench.scj.MclSafelet;
import org.jmclbench.scj.MissionOutput;
import org.jmclbench.scj.PlacedMissionInput;
import org.jmclbench.core.policy.OverrunPolicy;
import org.jmclbench.verification.Property;
import org.jmclbench.verification.jpf.Coverage;

/**
 * The real SCJ mission (scj-mission on rtsj-compat, virtual time) on a tiny synthetic sensor log,
 * as the program Java PathFinder explores. During the mission {@link CheckedRobot} checks P2 (the
 * robot's jobs take turns), P3 and P4 in every job; virtual time has a horizon, so a mission that never ends fails (P5) on the
 * path where it hangs. After the mission:
 * <ul>
 * <li>P5: the gate counted exactly as many ended events as there are events, and every event has
 * an outcome (done, late, skipped or terminated);
 * <li>P7: an event was dropped or aborted only as its policy says ({@link PolicyOracle}, on the
 * job records; a wrong decision is blamed on the gate);
 * <li>P3, the functional oracle: the completed jobs, replayed in the order they committed on a
 * fresh localizer of the shipped style, give the recorded estimates and covariances and, after
 * each job, the mission's particles, bit for bit; an event whose job did not complete has nothing
 * recorded. This sees what the robot does not show, such as a generator an aborted job advanced;
 * <li>each outcome reached is reported ({@link Coverage}), so a search that never aborted or
 * skipped a job fails as vacuous.
 * </ul>
 *
 * <p>Usage: {@code MissionDriver POLICY MEMORY ODOMETRY_EVENTS LASER_EVENTS PARTICLES POLL_INTERVAL
 * COVARIANCE [FAULT_CLASS]}; the fault ({@link CheckedConfiguration}) is the seam seeded bugs come in by.
 */
public final class MissionDriver extends PlacedMissionInput implements MissionOutput {
    /** Virtual time after which the mission must have ended: far beyond the last event's deadline. */
    static final long HORIZON_NS = 1_000_000_000L;
    /**
     * A job's virtual execution time: more than the 2 ms between an odometry event and the laser
     * event next to it (see {@link #readLaser}), far less than the 50 ms odometry period.
     */
    public static final long JOB_COST_NS = 5_000_000L;
    /** The outcome names reported per task ({@link Timeline#PREDICT}, {@link Timeline#UPDATE}) and outcome. */
    private static final String[][] OUTCOMES = {
        {"predict pending", "predict done", "predict late", "predict skipped", "predict terminated"},
        {"update pending", "update done", "update late", "update skipped", "update terminated"}};

    /** How far a laser event is from its odometry event (s), less than a job's execution time. */
    static final double LASER_OFFSET_S = 0.002;

    private JobRecords records;

    /** True: laser event k at the instant of odometry event k ({@link org.jmclbench.verification.MissionRun#atOdometryInstants}). */
    private final boolean coinciding;

    MissionDriver(int odometry, int laser, boolean coinciding) {
        super(odometry, laser, Playground.thesis(), 1.5, 1.0, 0.0);
        this.coinciding = coinciding;
    }

    public static void main(String[] args) throws ReflectiveOperationException {
        OverrunPolicy policy = OverrunPolicy.valueOf(args[0].toUpperCase());
        MclConfig mcl = MclConfig.builder().memory(MclConfig.Memory.valueOf(args[1].toUpperCase()))
                .particles(Integer.parseInt(args[4])).pollInterval(Integer.parseInt(args[5]))
                .covariance(Boolean.parseBoolean(args[6])).build();
        MissionDriver d = new MissionDriver(Integer.parseInt(args[2]), Integer.parseInt(args[3]),
                Boolean.parseBoolean(args[7]));
        Class<?> fault = args.length > 8 ? Class.forName(args[8]) : null;
        // Virtual time: the run is a function of the interleaving, not of the host's clock.
        System.setProperty("jmclbench.scj.meter", "none");
        // Non-daemon handler threads: JPF hands over at a thread's end only to a runnable non-daemon.
        System.setProperty("jmclbench.scj.daemon", "false");
        CheckedConfiguration config = new CheckedConfiguration(mcl, policy, fault);
        HorizonTimeSource clock = new HorizonTimeSource(HORIZON_NS, config);
        config.jobsTake(clock, JOB_COST_NS);
        TimeSource.install(clock);
        // Load the job code's classes before the mission, as an SCJ VM does before it starts and
        // as the JVM engine's class-loading mission does: JPF creates a class's objects (its
        // Class, its name) on first use, which must not count as a release's allocation.
        Localizer warm = config.newLocalizer(d.playground(), d.startX(), d.startY(), d.startTheta());
        warm.predict(0.01, 0.0, 0.01, AbortSignal.NEVER);
        warm.update(1.0, AbortSignal.NEVER);
        RunReport report = ScjRuntime.launch(new MclSafelet(config, d, d), 1);
        if (report == null || !report.succeeded()) {
            // A P3, P4 or P5 failure inside the mission ends it: that failure is the verdict.
            Throwable why = report == null ? null : report.failure();
            if (why != null && why.getCause() instanceof PropertyFailure) {
                throw (PropertyFailure) why.getCause();
            }
            throw new AssertionError("the mission failed" + (why == null ? "" : ": " + why.getMessage()), why);
        }
        d.checkEnded(config);
        d.checkPolicy(config);
        d.replay(config, mcl);
        d.reportOutcomes();
    }

    /** P5: every event ended once, as the gate counted and as the records say. */
    private void checkEnded(CheckedConfiguration config) {
        PropertyFailure p5 = new PropertyFailure(Property.P5, "an event did not end exactly once");
        p5.unless(records != null && records.size() == odometryCount() + laserCount(), config.gate(), "ended");
        p5.unless(config.gate().endedCount() == records.size(), config.gate(), "ended");
        for (int k = 0; k < records.size(); k++) {
            byte o = records.outcome[k];
            p5.unless(o == JobRecords.DONE || o == JobRecords.LATE || o == JobRecords.SKIPPED
                    || o == JobRecords.TERMINATED, config.gate(), "ended");
        }
    }

    /** P7, on the records ({@link PolicyOracle}); a wrong decision is the gate's. */
    private void checkPolicy(CheckedConfiguration config) {
        PolicyOracle.check(records, config.gate(), "admit", "abortRequested");
    }

    /** P3's oracle: the completed jobs replayed on a fresh localizer equal what the mission recorded. */
    private void replay(CheckedConfiguration config, MclConfig mcl) {
        Localizer mission = config.robot().jobLocalizer();
        Localizer fresh = config.shipped(playground(), startX(), startY(), startTheta());
        int odometry = odometryCount();
        int laser = laserCount();
        double[] dx = new double[odometry];
        double[] dy = new double[odometry];
        double[] dt = new double[odometry];
        readOdometry(new double[odometry], dx, dy, dt);
        double[] angle = new double[laser];
        readLaser(new double[laser], angle);
        PropertyFailure differs = new PropertyFailure(Property.P3,
                "the completed jobs replayed on a fresh localizer differ from what the mission recorded");
        Timeline t = records.timeline;
        int[] order = config.robot().completedJobs();
        boolean[] replayed = new boolean[records.size()];
        double[] cov = new double[6];
        double[] pose = new double[3];
        for (int j = 0; j < order.length; j++) {
            int k = order[j];
            boolean update = t.task(k) == Timeline.UPDATE;
            int i = t.taskIndex(k);
            boolean done = update ? fresh.update(angle[i], AbortSignal.NEVER)
                    : fresh.predict(dx[i], dy[i], dt[i], AbortSignal.NEVER);
            String job = update ? "update" : "predict";
            differs.unless(done && records.completed(k), mission, job);
            differs.unless(same(fresh.estimateX(), records.estX[k]) && same(fresh.estimateY(), records.estY[k])
                    && same(fresh.estimateTheta(), records.estTheta[k]), mission, job);
            if (update && records.cov != null) {
                fresh.covariance(cov);
                for (int c = 0; c < 6; c++) {
                    differs.unless(same(cov[c], records.cov[6 * k + c]), mission, job);
                }
            }
            // Every particle, as the mission's localizer had them right after this job.
            differs.unless(CheckedRobot.fingerprint(fresh, pose, cov) == config.robot().stateAfter(j), mission, job);
            replayed[k] = true;
        }
        for (int k = 0; k < records.size(); k++) {
            // An event whose job did not complete has no result recorded.
            String job = t.task(k) == Timeline.UPDATE ? "update" : "predict";
            differs.unless(replayed[k] == records.completed(k), config.robot(), job);
            differs.unless(replayed[k] || Double.isNaN(records.estX[k]) && Double.isNaN(records.estY[k])
                    && Double.isNaN(records.estTheta[k]), config.robot(), job);
        }
        double[] a = new double[3];
        double[] b = new double[3];
        for (int i = 0; i < mission.particleCount(); i++) {
            mission.particle(i, a);
            fresh.particle(i, b);
            differs.unless(same(a[0], b[0]) && same(a[1], b[1]) && same(a[2], b[2]), mission, "particle");
        }
    }

    private static boolean same(double a, double b) {
        return Double.doubleToRawLongBits(a) == Double.doubleToRawLongBits(b);
    }

    /** Reports each (task, outcome) this path reached, for the vacuity guard. */
    private void reportOutcomes() {
        for (int k = 0; k < records.size(); k++) {
            Coverage.reached(OUTCOMES[records.timeline.task(k)][records.outcome[k]]);
        }
    }

    @Override
    public void readOdometry(double[] time, double[] dx, double[] dy, double[] dtheta) {
        for (int k = 0; k < odometryCount(); k++) {
            time[k] = 0.05 * k;
            dx[k] = 0.01;
            dy[k] = 0.0;
            dtheta[k] = 0.01;
        }
    }

    @Override
    public void readLaser(double[] time, double[] angle) {
        // A job takes 5 ms of virtual time: laser event k falls 2 ms after odometry event k (k even:
        // within that predict) or 2 ms before it (k odd: that predict falls within the update);
        // coinciding, at the instant of odometry event k.
        double offset = coinciding ? 0.0 : LASER_OFFSET_S;
        for (int k = 0; k < laserCount(); k++) {
            time[k] = 0.05 * k + (k % 2 == 0 ? offset : -offset);
            angle[k] = 1.0 + 0.5 * k;
        }
    }

    @Override
    public void missionEnded(JobRecords records) {
        this.records = records;
    }

    @Override
    public void releaseEnding(int area) {
        // the memory rules are checked by the listeners, not measured
    }
}
