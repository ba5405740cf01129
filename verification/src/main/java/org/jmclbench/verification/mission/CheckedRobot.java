package org.jmclbench.verification.mission;

import org.jmclbench.core.mcl.AbortSignal;
import org.jmclbench.core.mcl.Localizer;
import org.jmclbench.core.record.JobRecords;
import org.jmclbench.scj.ImmortalEntry;
import org.jmclbench.scj.Robot;
import org.jmclbench.verification.Property;

/**
 * The mission's robot with P3 and P4 checked around each job, and the completed jobs logged in
 * their order for the driver's functional oracle.
 * <ul>
 * <li>P3: when a job returns false (aborted), everything the robot shows is bit-identical to
 * what it was before the job: every particle, the estimate, the covariance, and what is recorded
 * for the event (its estimate and covariance). The generator is not visible here; the oracle
 * sees it, as a completed job's result after an aborted one.
 * <li>P4: once a poll has seen the abort request, the job polls no more and returns false, so
 * the request is honoured at the first poll after it was made; and a completed job polled at
 * least once per poll interval of particles (N particles, interval I: ceil(N / I) polls, as any
 * particle loop that polls every I particles makes), so a job polling every k-th interval is
 * seen when N exceeds two intervals. The static rule bounds the steps between polls exactly.
 * </ul>
 * Each job takes virtual time before it polls ({@link #executesIn}), so that a release can fall
 * within it: events at one instant are decided before any of their jobs starts.
 * Allocation-free after construction: a violation throws a failure made beforehand, so the
 * release-allocation rule does not report it as an allocation. Jobs run one at a time (they
 * hold this robot's monitor), so one poll watch serves both tasks.
 */
public class CheckedRobot extends Robot {
    private final double[] pose = new double[3];
    private final double[] cov = new double[6];
    private final PollWatch watch = new PollWatch();
    private final PropertyFailure changed = new PropertyFailure(Property.P3, "an aborted job changed the robot");
    private final PropertyFailure recorded = new PropertyFailure(Property.P3,
            "an aborted job changed what is recorded for its event");
    private final PropertyFailure completedAfterAbort = new PropertyFailure(Property.P4,
            "a job completed after a poll saw its abort request");
    private final PropertyFailure tooFewPolls = new PropertyFailure(Property.P4,
            "a completed job polled less than once per poll interval of particles");
    private final int[] completed;
    private final long[] completedState;
    private int completedCount;
    private int minimumPolls;
    private HorizonTimeSource clock;
    private long costNs;

    public CheckedRobot(Localizer localizer, ImmortalEntry entry) {
        super(localizer, entry);
        this.completed = new int[entry.size()];
        this.completedState = new long[entry.size()];
        watch.late = new PropertyFailure(Property.P4, "a job went on after a poll saw its abort request");
    }

    /** A completed job must poll at least once per {@code pollInterval} particles. */
    void expectPolls(int pollInterval) {
        minimumPolls = (localizer.particleCount() + pollInterval - 1) / pollInterval;
    }

    /** Each job takes {@code costNs} of {@code clock}'s virtual time, before its first poll. */
    void executesIn(HorizonTimeSource clock, long costNs) {
        this.clock = clock;
        this.costNs = costNs;
    }

    @Override
    public synchronized boolean predict(int k, AbortSignal abort) {
        return checked(k, abort, false);
    }

    @Override
    public synchronized boolean update(int k, AbortSignal abort) {
        return checked(k, abort, true);
    }

    /** Runs the robot's job for event k (update or predict) with its abort signal watched, then checks how it ended. */
    private boolean checked(int k, AbortSignal abort, boolean update) {
        String job = update ? "update" : "predict";
        long before = fingerprint();
        long record = record(k);
        watch.arm(abort, localizer, job);
        if (clock != null) {
            clock.execute(costNs);
        }
        boolean done = update ? super.update(k, watch) : super.predict(k, watch);
        jobEnded(k, done, before, record, job);
        return done;
    }

    private void jobEnded(int k, boolean done, long before, long record, String job) {
        completedAfterAbort.unless(!(done && watch.seen), localizer, job);
        tooFewPolls.unless(!done || watch.polls >= minimumPolls, localizer, job);
        if (done) {
            completedState[completedCount] = fingerprint();
            completed[completedCount++] = k;
            return;
        }
        changed.unless(fingerprint() == before, localizer, job);
        recorded.unless(record(k) == record, this, job);
    }

    /** The events whose jobs completed, in the order they committed. */
    int[] completedJobs() {
        int[] out = new int[completedCount];
        System.arraycopy(completed, 0, out, 0, completedCount);
        return out;
    }

    /** The localizer's {@link #fingerprint(Localizer, double[], double[])} after the i-th completed job. */
    long stateAfter(int i) {
        return completedState[i];
    }

    /** The job's abort signal, watched: a poll after one that returned true is a P4 violation. */
    private static final class PollWatch implements AbortSignal {
        private AbortSignal job;
        private Object localizer;
        private String method;
        private boolean seen;
        private int polls;
        private PropertyFailure late;

        void arm(AbortSignal abort, Object localizer, String method) {
            this.job = abort;
            this.localizer = localizer;
            this.method = method;
            seen = false;
            polls = 0;
        }

        @Override
        public boolean abortRequested() {
            late.unless(!seen, localizer, method);
            polls++;
            seen = job.abortRequested();
            return seen;
        }
    }

    private long fingerprint() {
        return fingerprint(localizer, pose, cov);
    }

    /** A hash of every bit of a localizer's visible state; {@code pose} and {@code cov} are scratch. */
    public static long fingerprint(Localizer localizer, double[] pose, double[] cov) {
        long h = Double.doubleToRawLongBits(localizer.estimateX());
        h = h * 31 + Double.doubleToRawLongBits(localizer.estimateY());
        h = h * 31 + Double.doubleToRawLongBits(localizer.estimateTheta());
        localizer.covariance(cov);
        for (int i = 0; i < 6; i++) {
            h = h * 31 + Double.doubleToRawLongBits(cov[i]);
        }
        for (int i = 0; i < localizer.particleCount(); i++) {
            localizer.particle(i, pose);
            h = h * 31 + Double.doubleToRawLongBits(pose[0]);
            h = h * 31 + Double.doubleToRawLongBits(pose[1]);
            h = h * 31 + Double.doubleToRawLongBits(pose[2]);
        }
        return h;
    }

    /** A hash of what is recorded for event k's result (estimate, covariance). */
    private long record(int k) {
        JobRecords r = entry.records;
        long h = Double.doubleToRawLongBits(r.estX[k]);
        h = h * 31 + Double.doubleToRawLongBits(r.estY[k]);
        h = h * 31 + Double.doubleToRawLongBits(r.estTheta[k]);
        if (r.cov != null) {
            for (int c = 0; c < 6; c++) {
                h = h * 31 + Double.doubleToRawLongBits(r.cov[6 * k + c]);
            }
        }
        return h;
    }
}
