package org.jmclbench.verification.mission;

import org.jmclbench.core.mcl.AbortSignal;
import org.jmclbench.core.mcl.Localizer;

/**
 * P3 and P4 on the real localizer: wraps the mission's localizer and its jobs' abort signal.
 * <ul>
 * <li>P3: whenever a job returns false (aborted), everything the robot shows (every particle,
 * the estimate, the covariance) is bit-identical to what it was before the job.
 * <li>P4: once a poll has seen the abort request, the job polls no more and returns false: it
 * is honoured at the first poll after it was made. The static rule (every particle loop polls
 * at least every poll interval) bounds the particle steps before that poll.
 * </ul>
 * Allocation-free after construction, so it does not disturb the release-allocation check.
 * Jobs run one at a time (they hold the robot's monitor), so one poll watch serves both tasks.
 */
public final class CheckedLocalizer extends DelegatingLocalizer {
    private final double[] pose = new double[3];
    private final double[] cov = new double[6];
    private final PollWatch watch = new PollWatch();

    public CheckedLocalizer(Localizer inner) {
        super(inner);
    }

    @Override
    public boolean predict(double dx, double dy, double dtheta, AbortSignal abort) {
        long before = fingerprint();
        watch.arm(abort);
        boolean done = inner.predict(dx, dy, dtheta, watch);
        jobEnded(done, before);
        return done;
    }

    @Override
    public boolean update(double angle, AbortSignal abort) {
        long before = fingerprint();
        watch.arm(abort);
        boolean done = inner.update(angle, watch);
        jobEnded(done, before);
        return done;
    }

    private void jobEnded(boolean done, long before) {
        MissionDriver.check(!(done && watch.seen), "P4 a job completed after a poll saw its abort request");
        if (!done) {
            MissionDriver.check(fingerprint() == before, "P3 an aborted job changed the robot");
        }
    }

    /** The job's abort signal, watched: a poll after one that returned true is a P4 violation. */
    private static final class PollWatch implements AbortSignal {
        private AbortSignal job;
        private boolean seen;

        void arm(AbortSignal abort) {
            job = abort;
            seen = false;
        }

        @Override
        public boolean abortRequested() {
            MissionDriver.check(!seen, "P4 a job went on after a poll saw its abort request");
            seen = job.abortRequested();
            return seen;
        }
    }

    /** A hash of every bit of the robot's visible state. */
    private long fingerprint() {
        long h = Double.doubleToRawLongBits(inner.estimateX());
        h = h * 31 + Double.doubleToRawLongBits(inner.estimateY());
        h = h * 31 + Double.doubleToRawLongBits(inner.estimateTheta());
        inner.covariance(cov);
        for (int i = 0; i < 6; i++) {
            h = h * 31 + Double.doubleToRawLongBits(cov[i]);
        }
        for (int i = 0; i < inner.particleCount(); i++) {
            inner.particle(i, pose);
            h = h * 31 + Double.doubleToRawLongBits(pose[0]);
            h = h * 31 + Double.doubleToRawLongBits(pose[1]);
            h = h * 31 + Double.doubleToRawLongBits(pose[2]);
        }
        return h;
    }
}
