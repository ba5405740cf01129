package org.jmclbench.verification.mission;

import org.jmclbench.core.mcl.AbortSignal;
import org.jmclbench.core.mcl.DelegatingLocalizer;
import org.jmclbench.core.mcl.Localizer;
import org.jmclbench.core.record.JobRecords;
import org.jmclbench.scj.ImmortalEntry;
import org.jmclbench.scj.Robot;
import org.jmclbench.verification.Property;

/**
 * The mission's robot with P2, P3 and P4 checked in every job, and the completed jobs logged in
 * their order for the driver's functional oracle. It adds no lock: the shipped {@link Robot}'s
 * synchronized predict and update run as shipped, and the checks run inside them, in the
 * localizer the robot is given ({@link Jobs}, around the configured one), so that the searches
 * see the shipped code's locking and not ours.
 * <ul>
 * <li>P2: no job enters the localizer while another is in it (the robot's monitor makes the
 * tasks take turns; without it two jobs work on one particle set, a data race the P2 searches do
 * not look for, as they leave the localizer's fields out). Blamed on the job that works without
 * the robot's monitor.
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
 * release-allocation rule does not report it as an allocation. A violation is located at the
 * configured localizer (P3, P4) or this robot (P2, and a record changed by an aborted job).
 */
public class CheckedRobot extends Robot {
    private final Jobs jobs;
    private final PropertyFailure recorded = new PropertyFailure(Property.P3,
            "an aborted job changed what is recorded for its event");

    public CheckedRobot(Localizer localizer, ImmortalEntry entry) {
        super(new Jobs(localizer, entry.size()), entry);
        this.jobs = (Jobs) this.localizer;
        jobs.robot = this;
    }

    /** A completed job must poll at least once per {@code pollInterval} particles. */
    void expectPolls(int pollInterval) {
        jobs.minimumPolls = (jobs.particleCount() + pollInterval - 1) / pollInterval;
    }

    /** Each job takes {@code costNs} of {@code clock}'s virtual time, before its first poll. */
    void executesIn(HorizonTimeSource clock, long costNs) {
        jobs.clock = clock;
        jobs.costNs = costNs;
    }

    // Not synchronized: the shipped predict and update take the robot's monitor, or do not. The
    // record is event k's alone (no other job writes it), so it is read here, outside the monitor;
    // each task's handler runs one job at a time, so its event is passed on in a field of its own.
    @Override
    public boolean predict(int k, AbortSignal abort) {
        jobs.predictEvent = k;
        long record = record(k);
        return recordKept(k, record, super.predict(k, abort), "predict");
    }

    @Override
    public boolean update(int k, AbortSignal abort) {
        jobs.updateEvent = k;
        long record = record(k);
        return recordKept(k, record, super.update(k, abort), "update");
    }

    /** P3 of the record: an aborted job left event k's record as it was ({@code before}); returns {@code done}. */
    private boolean recordKept(int k, long before, boolean done, String job) {
        recorded.unless(done || record(k) == before, this, job);
        return done;
    }

    /** The localizer the jobs work on, as configured (without the checks around it). */
    Localizer jobLocalizer() {
        return jobs.inner();
    }

    /** The events whose jobs completed, in the order they committed. */
    int[] completedJobs() {
        int[] out = new int[jobs.completedCount];
        System.arraycopy(jobs.completed, 0, out, 0, jobs.completedCount);
        return out;
    }

    /** The localizer's {@link #fingerprint(Localizer, double[], double[])} after the i-th completed job. */
    long stateAfter(int i) {
        return jobs.completedState[i];
    }

    /**
     * The configured localizer as the robot's jobs reach it: inside the robot's synchronized
     * predict and update, where it checks P2, P3 and P4 around each job. Only the jobs are
     * watched; the robot's reads of the estimate and covariance go straight through.
     */
    private static final class Jobs extends DelegatingLocalizer {
        private final double[] pose = new double[3];
        private final double[] cov = new double[6];
        private final PollWatch watch = new PollWatch();
        private final PropertyFailure together = new PropertyFailure(Property.P2,
                "two jobs worked on the robot's localizer at once");
        private final PropertyFailure changed = new PropertyFailure(Property.P3, "an aborted job changed the robot");
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
        private Robot robot;
        private int predictEvent;
        private int updateEvent;
        // The job in the localizer ("predict", "update"), or null: a constant, so keeping it allocates nothing.
        private String occupant;

        Jobs(Localizer inner, int events) {
            super(inner);
            this.completed = new int[events];
            this.completedState = new long[events];
            watch.late = new PropertyFailure(Property.P4, "a job went on after a poll saw its abort request");
        }

        Localizer inner() {
            return inner;
        }

        @Override
        public boolean predict(double dx, double dy, double dtheta, AbortSignal abort) {
            long before = entered(abort, "predict");
            try {
                boolean done = inner.predict(dx, dy, dtheta, watch);
                ended(done, before, "predict", predictEvent);
                return done;
            } finally {
                occupant = null;
            }
        }

        @Override
        public boolean update(double angle, AbortSignal abort) {
            long before = entered(abort, "update");
            try {
                boolean done = inner.update(angle, watch);
                ended(done, before, "update", updateEvent);
                return done;
            } finally {
                occupant = null;
            }
        }

        /** P2 on entry; arms the poll watch, takes the job's virtual time; returns the state before the job. */
        private long entered(AbortSignal abort, String job) {
            if (occupant != null) {
                // One of the two works without the robot's monitor: this one, unless it holds it.
                throw together.at(robot, Thread.holdsLock(robot) ? occupant : job);
            }
            occupant = job;
            long before = fingerprint(inner, pose, cov);
            watch.arm(abort, inner, job);
            if (clock != null) {
                clock.execute(costNs);
            }
            return before;
        }

        private void ended(boolean done, long before, String job, int k) {
            completedAfterAbort.unless(!(done && watch.seen), inner, job);
            tooFewPolls.unless(!done || watch.polls >= minimumPolls, inner, job);
            if (done) {
                completedState[completedCount] = fingerprint(inner, pose, cov);
                completed[completedCount++] = k;
                return;
            }
            changed.unless(fingerprint(inner, pose, cov) == before, inner, job);
        }
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
