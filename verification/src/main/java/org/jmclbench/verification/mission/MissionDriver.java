package org.jmclbench.verification.mission;

import org.jmclbench.core.mcl.AbortSignal;
import org.jmclbench.core.mcl.Localizer;
import org.jmclbench.core.mcl.MclConfig;
import org.jmclbench.core.mcl.Playground;
import org.jmclbench.core.policy.OverrunPolicy;
import org.jmclbench.core.record.JobRecords;
import org.jmclbench.rtsjcompat.RunReport;
import org.jmclbench.rtsjcompat.ScjRuntime;
import org.jmclbench.scj.MclSafelet;
import org.jmclbench.scj.MissionConfiguration;
import org.jmclbench.scj.MissionInput;
import org.jmclbench.scj.MissionOutput;

/**
 * The real SCJ mission (scj-mission on rtsj-compat, virtual time) on a tiny synthetic sensor log,
 * as the program Java PathFinder explores. After the mission it checks P5 from the job records:
 * every event ended exactly once (done, late, skipped or terminated), none left pending.
 *
 * <p>Usage: {@code MissionDriver POLICY ODOMETRY_EVENTS LASER_EVENTS PARTICLES [CONFIGURATION_CLASS]};
 * the configuration class (a {@link CheckedConfiguration}) is the seam seeded bugs come in by.
 */
public final class MissionDriver implements MissionInput, MissionOutput {
    private final int odometry;
    private final int laser;
    private JobRecords records;

    MissionDriver(int odometry, int laser) {
        this.odometry = odometry;
        this.laser = laser;
    }

    public static void main(String[] args) throws ReflectiveOperationException {
        OverrunPolicy policy = OverrunPolicy.ofLabel(args[0]);
        if (policy == null) {
            throw new IllegalArgumentException("no policy '" + args[0] + "'");
        }
        MissionDriver d = new MissionDriver(Integer.parseInt(args[1]), Integer.parseInt(args[2]));
        int particles = Integer.parseInt(args[3]);
        // Virtual time: the run is a function of the interleaving, not of the host's clock.
        System.setProperty("jmclbench.scj.time", "virtual");
        System.setProperty("jmclbench.scj.meter", "none");
        // Non-daemon handler threads: JPF hands over at a thread's end only to a runnable non-daemon.
        System.setProperty("jmclbench.scj.daemon", "false");
        Class<?> c = Class.forName(args.length > 4 ? args[4] : CheckedConfiguration.class.getName());
        MissionConfiguration config = (MissionConfiguration) c
                .getConstructor(MclConfig.class, OverrunPolicy.class, double.class)
                .newInstance(MclConfig.of(particles), policy, 1.0);
        // Load the job code's classes before the mission, as an SCJ VM does before it starts and
        // as the JVM engine's class-loading mission does: JPF creates a class's objects (its
        // Class, its name) on first use, which must not count as a release's allocation.
        Localizer warm = config.newLocalizer(d.playground(), d.startX(), d.startY(), d.startTheta());
        warm.predict(0.01, 0.0, 0.01, AbortSignal.NEVER);
        warm.update(1.0, AbortSignal.NEVER);
        RunReport report = ScjRuntime.launch(new MclSafelet(config, d, d), 1);
        if (report == null || !report.succeeded()) {
            // A P3 or P4 assertion inside a release ends the mission: say which.
            Throwable why = report == null ? null : report.failure();
            throw new AssertionError("the mission failed" + (why == null ? "" : ": " + why.getMessage()), why);
        }
        check(d.records != null, "P5 the mission ended without its records");
        check(d.records.size() == d.odometry + d.laser, "P5 an event is missing from the records");
        for (int k = 0; k < d.records.size(); k++) {
            byte o = d.records.outcome[k];
            check(o == JobRecords.DONE || o == JobRecords.LATE || o == JobRecords.SKIPPED
                    || o == JobRecords.TERMINATED, "P5 an event never ended");
        }
    }

    static void check(boolean ok, String what) {
        if (!ok) {
            throw new AssertionError(what);
        }
    }

    @Override
    public int odometryCount() {
        return odometry;
    }

    @Override
    public int laserCount() {
        return laser;
    }

    @Override
    public void readOdometry(double[] time, double[] dx, double[] dy, double[] dtheta) {
        for (int k = 0; k < odometry; k++) {
            time[k] = 0.05 * k;
            dx[k] = 0.01;
            dy[k] = 0.0;
            dtheta[k] = 0.01;
        }
    }

    @Override
    public void readLaser(double[] time, double[] angle) {
        // Virtual time stands still while a job runs, so a job overruns only when another release
        // falls at the same instant: laser event k coincides with odometry event k.
        for (int k = 0; k < laser; k++) {
            time[k] = 0.05 * k;
            angle[k] = 1.0 + 0.5 * k;
        }
    }

    @Override
    public Playground playground() {
        return Playground.thesis();
    }

    @Override
    public double startX() {
        return 1.5;
    }

    @Override
    public double startY() {
        return 1.0;
    }

    @Override
    public double startTheta() {
        return 0.0;
    }

    @Override
    public void missionEnded(JobRecords records) {
        this.records = records;
    }
}
