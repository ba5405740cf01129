package org.jmclbench.verification.toy;

import org.jmclbench.verification.Property;
import org.jmclbench.verification.mission.PropertyFailure;

/**
 * A small SCJ-like mission that proves the JPF machinery before the real mission exists: a
 * dispatcher releases events to one handler thread that runs terminable particle jobs on a
 * shared robot, under the skip, terminate or queue policy. Properties P3-P5 are checked by the
 * program itself (an AssertionError is JPF's uncaught-exception violation); P1, P2 and P6 by JPF
 * and our listeners. A {@link ToyFault} seeds one bug per property.
 *
 * <p>Usage (inside JPF): {@code ToyMission POLICY EVENTS PARTICLES POLL FAULT}.
 */
public final class ToyMission {
    static final int NONE = 0;
    static final int PROCESSED = 1;
    static final int SKIPPED = 2;
    static final int TERMINATED = 3;

    final String policy;
    final int poll;
    final ToyFault fault;
    final ToyRobot robot;
    final ToyHandler handler;
    /** Outcome of each event; guarded by itself. */
    final int[] outcome;
    /** Releases waiting for the handler (queue: all; skip/terminate: at most one); guarded by this. */
    private final int[] pending;
    private int head;
    private int tail;
    private boolean busy;
    private boolean finished;
    private boolean abortRequested;
    /** The job's step at its last poll, and that step when an abort was requested. */
    private int lastPollStep;
    private int requestedAtStep;
    /** The violations the program reports, made before the run: reporting one allocates nothing. */
    final PropertyFailure robotChanged = new PropertyFailure(Property.P3, "an aborted job changed the robot");
    private final PropertyFailure lateAbort = new PropertyFailure(Property.P4,
            "abort honoured later than the poll interval");
    private final PropertyFailure endedTwice = new PropertyFailure(Property.P5, "an event ended twice");

    ToyMission(String policy, int events, int particles, int poll, ToyFault fault) {
        this.policy = policy;
        this.poll = poll;
        this.fault = fault;
        this.robot = new ToyRobot(particles);
        this.outcome = new int[events];
        this.pending = new int[events];
        this.handler = new ToyHandler(this);
    }

    public static void main(String[] args) throws InterruptedException {
        ToyMission m = new ToyMission(args[0], Integer.parseInt(args[1]), Integer.parseInt(args[2]),
                Integer.parseInt(args[3]), ToyFault.valueOf(args[4]));
        Thread t = new Thread(m.handler, "update");
        t.start();
        for (int e = 0; e < m.outcome.length; e++) {
            m.release(e);
        }
        m.finish();
        t.join();
        m.checkEveryEventEndedOnce();
    }

    /** The dispatcher's release of event e, decided by the policy. */
    void release(int e) {
        if (fault == ToyFault.UNGUARDED_READ) {
            robot.estimateUnguarded();
        }
        if (fault == ToyFault.LOCK_INVERSION) {
            synchronized (outcome) {
                robot.estimate();
            }
        }
        synchronized (this) {
            boolean queue = policy.equals("queue");
            if (!queue && (busy || head != tail)) {
                if (policy.equals("terminate") && busy && !abortRequested) {
                    abortRequested = true;
                    requestedAtStep = lastPollStep;
                } else if (head != tail) {
                    end(pending[--tail], SKIPPED);
                }
                if (policy.equals("skip")) {
                    end(e, SKIPPED);
                    return;
                }
            }
            if (fault == ToyFault.LOST_RELEASE && head != tail) {
                return;
            }
            pending[tail++] = e;
            notifyAll();
        }
    }

    synchronized void finish() {
        finished = true;
        notifyAll();
    }

    /** The handler's wait for its next release; -1 when the mission is over. */
    synchronized int next() throws InterruptedException {
        busy = false;
        while (head == tail && !finished) {
            wait();
        }
        if (head == tail) {
            return -1;
        }
        busy = true;
        abortRequested = false;
        lastPollStep = 0;
        return pending[head++];
    }

    /** The job's poll of the abort request at particle step {@code step}; checks P4's bound. */
    synchronized boolean abortRequested(int step) {
        if (abortRequested) {
            lateAbort.unless(step - requestedAtStep <= poll, handler, "handleAsyncEvent");
            return true;
        }
        lastPollStep = step;
        return false;
    }

    void end(int e, int how) {
        synchronized (outcome) {
            endedTwice.unless(outcome[e] == NONE, this, "end");
            outcome[e] = how;
        }
    }

    void checkEveryEventEndedOnce() {
        PropertyFailure never = new PropertyFailure(Property.P5, "an event never ended");
        synchronized (outcome) {
            for (int e = 0; e < outcome.length; e++) {
                never.unless(outcome[e] != NONE, this, "release");
            }
        }
    }
}
