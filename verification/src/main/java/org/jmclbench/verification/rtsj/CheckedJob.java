package org.jmclbench.verification.rtsj;

import org.jmclbench.core.mcl.AbortSignal;
import org.jmclbench.core.mcl.Localizer;
import org.jmclbench.core.record.JobRecords;
import org.jmclbench.core.timeline.Timeline;
import org.jmclbench.verification.Property;
import org.jmclbench.verification.mission.CheckedRobot;
import org.jmclbench.verification.mission.HorizonTimeSource;
import org.jmclbench.verification.mission.PropertyFailure;
import org.jmclbench.workload.release.EventJob;

/**
 * The rtsj engine's job with P3 checked around it: a job that did not complete (an AIE unwound
 * it, or it stopped on its signal) leaves every particle, the estimate, the covariance and its
 * event's record bit-identical; completed jobs are logged in their commit order with the state
 * after each, for the oracle ({@link #replayCompleted}). A violation is kept and thrown: the
 * replay records it as a handler's failure, and the driver throws it again, located. Each job
 * takes virtual time before it runs ({@link HorizonTimeSource#execute}), so that a release can fall
 * within it: events at one instant are decided before any of their jobs starts.
 */
final class CheckedJob implements EventJob {
    private final EventJob inner;
    private final Localizer localizer;
    private final JobRecords records;
    private final Timeline timeline;
    private final double[] pose = new double[3];
    private final double[] cov = new double[6];
    private final int[] order;
    private final long[] after;
    private int completed;
    private volatile PropertyFailure failure;
    private HorizonTimeSource clock;
    private long costNs;

    CheckedJob(EventJob inner, Localizer localizer, JobRecords records) {
        this.inner = inner;
        this.localizer = localizer;
        this.records = records;
        this.timeline = records.timeline;
        this.order = new int[records.size()];
        this.after = new long[records.size()];
    }

    /** Each job takes {@code costNs} of {@code clock}'s virtual time, before the job's own code. */
    void executesIn(HorizonTimeSource clock, long costNs) {
        this.clock = clock;
        this.costNs = costNs;
    }

    @Override
    public boolean run(int k, AbortSignal abort) {
        long before = CheckedRobot.fingerprint(localizer, pose, cov);
        boolean done = false;
        try {
            if (clock != null) {
                clock.execute(costNs);
                // a scheduling point: a release whose time has come may fire at this job before its
                // first delivery point, which no synchronisation action precedes (without it no path
                // reached "predict interrupted": the clock's monitor is inside rtsj-compat)
                Thread.yield();
            }
            done = inner.run(k, abort);
        } finally {
            if (done) {
                order[completed] = k;
                after[completed++] = CheckedRobot.fingerprint(localizer, pose, cov);
            } else {
                String job = timeline.task(k) == Timeline.UPDATE ? "update" : "predict";
                check(CheckedRobot.fingerprint(localizer, pose, cov) == before && unrecorded(k), job,
                        "an interrupted job changed the robot or its event's record");
            }
        }
        return done;
    }

    private boolean unrecorded(int k) {
        return Double.isNaN(records.estX[k]) && Double.isNaN(records.estY[k]) && Double.isNaN(records.estTheta[k]);
    }

    private void check(boolean ok, String job, String what) {
        if (!ok) {
            PropertyFailure f = new PropertyFailure(Property.P3, what).at(localizer, job);
            if (failure == null) {
                failure = f;
            }
            throw f;
        }
    }

    /** Throws the first violation seen during the replay, if any. */
    void rethrow() {
        if (failure != null) {
            throw failure;
        }
    }

    /**
     * P3's oracle: the completed jobs replayed in their commit order on {@code fresh} give the
     * recorded estimates and, after each, the replay's particles bit for bit; an event whose job
     * did not complete has nothing recorded.
     */
    void replayCompleted(Localizer fresh, double[] dx, double[] dy, double[] dtheta, double[] angle) {
        boolean[] done = new boolean[records.size()];
        for (int j = 0; j < completed; j++) {
            int k = order[j];
            int i = timeline.taskIndex(k);
            boolean update = timeline.task(k) == Timeline.UPDATE;
            String job = update ? "update" : "predict";
            boolean ok = update ? fresh.update(angle[i], AbortSignal.NEVER)
                    : fresh.predict(dx[i], dy[i], dtheta[i], AbortSignal.NEVER);
            check(ok && CheckedRobot.fingerprint(fresh, pose, cov) == after[j]
                    && same(fresh.estimateX(), records.estX[k]) && same(fresh.estimateY(), records.estY[k])
                    && same(fresh.estimateTheta(), records.estTheta[k]), job,
                    "the completed jobs replayed on a fresh localizer differ from the replay's");
            done[k] = true;
        }
        for (int k = 0; k < records.size(); k++) {
            check(done[k] || unrecorded(k), timeline.task(k) == Timeline.UPDATE ? "update" : "predict",
                    "an event whose job did not complete has a result recorded");
        }
    }

    private static boolean same(double a, double b) {
        return Double.doubleToRawLongBits(a) == Double.doubleToRawLongBits(b);
    }
}
