package org.jmclbench.scj;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import javax.realtime.AbsoluteTime;

import org.jmclbench.core.mcl.AbortAt;
import org.jmclbench.core.mcl.AbortSignal;
import org.jmclbench.core.mcl.MclConfig;
import org.jmclbench.core.mcl.Playground;
import org.jmclbench.core.policy.OverrunPolicy;
import org.jmclbench.core.record.JobRecords;
import org.jmclbench.core.timeline.Timeline;
import org.junit.jupiter.api.Test;

/**
 * The robot and gate without threads: an aborted job, at any poll, leaves the robot
 * bit-identical (the terminate policy's promise), in both memory styles; the gate admits and
 * aborts as each policy says.
 */
class RobotTest {
    private static final int PARTICLES = 40;
    private static final int POLL = 8; // five polls per loop over the particles

    /** Aborts at the n-th poll (1-based). */
    @Test
    void anAbortedJobLeavesTheRobotBitIdentical() {
        for (MclConfig.Memory memory : new MclConfig.Memory[] {MclConfig.Memory.PREALLOCATED, MclConfig.Memory.SCOPED}) {
            MissionConfiguration c = new MissionConfiguration(MclConfig.builder().particles(PARTICLES).pollInterval(POLL)
                    .memory(memory).covariance(true).build(), OverrunPolicy.TERMINATE, 1.0);
            ImmortalEntry entry = new ImmortalEntry(new SyntheticInput(1.0), c);
            long[] reference = trace(c, entry, -1, 0);
            int aborted = 0;
            for (int victim = 3; victim < 9; victim++) {
                for (int at = 1; at <= 16; at++) {
                    long[] t = trace(c, entry, victim, at);
                    if (t == null) {
                        continue; // fewer polls than at: the job completed, nothing to compare
                    }
                    aborted++;
                    for (int i = 0; i < reference.length; i++) {
                        assertEquals(reference[i], t[i], memory + ": event " + victim + " aborted at poll " + at
                                + " changed value " + i);
                    }
                }
            }
            assertTrue(aborted >= 20, "too few aborts to prove anything: " + aborted);
        }
    }

    /**
     * Every event in order on a fresh robot; event {@code victim} is first tried with an abort at
     * poll {@code at} (which must leave everything as it was) and then run to completion. Returns
     * the bits of every committed estimate and covariance, or null when the victim never polled {@code at} times.
     */
    private static long[] trace(MissionConfiguration c, ImmortalEntry entry, int victim, int at) {
        entry.records.clear();
        Robot robot = c.newRobot(c.newLocalizer(entry.playground, entry.startX, entry.startY, entry.startTheta), entry);
        Timeline t = entry.timeline;
        for (int k = 0; k < t.size(); k++) {
            if (k == victim) {
                AbortAt signal = new AbortAt(at);
                boolean completed = run(robot, t, k, signal);
                if (signal.polls() < at) {
                    return null;
                }
                assertFalse(completed, "a job asked to abort at poll " + at + " completed");
            }
            assertTrue(run(robot, t, k, AbortSignal.NEVER));
        }
        JobRecords r = entry.records;
        long[] bits = new long[t.size() * 9];
        for (int k = 0; k < t.size(); k++) {
            bits[9 * k] = Double.doubleToRawLongBits(r.estX[k]);
            bits[9 * k + 1] = Double.doubleToRawLongBits(r.estY[k]);
            bits[9 * k + 2] = Double.doubleToRawLongBits(r.estTheta[k]);
            for (int i = 0; i < 6; i++) {
                bits[9 * k + 3 + i] = Double.doubleToRawLongBits(r.cov[6 * k + i]);
            }
        }
        return bits;
    }

    /**
     * Every predict and update job works holding the robot's monitor: under terminate a job
     * admitted while the previous one polls towards its abort, and under queue the two tasks'
     * handlers, reach the one localizer at once, and only the monitor makes them take turns. The
     * JPF searches cannot see a robot job without it (the mutation score's
     * robot-predict-unsynchronised): the mission's job runner holds the monitor around every job too.
     */
    @Test
    void everyJobWorksHoldingTheRobotsMonitor() {
        MissionConfiguration c = new MissionConfiguration(MclConfig.builder().particles(PARTICLES).pollInterval(POLL)
                .covariance(true).build(), OverrunPolicy.TERMINATE, 1.0);
        ImmortalEntry entry = new ImmortalEntry(new SyntheticInput(1.0), c);
        Robot robot = c.newRobot(c.newLocalizer(entry.playground, entry.startX, entry.startY, entry.startTheta), entry);
        Timeline t = entry.timeline;
        boolean[] tasks = new boolean[2];
        for (int k = 0; k < t.size(); k++) {
            MonitorAtPoll poll = new MonitorAtPoll(robot);
            assertTrue(run(robot, t, k, poll));
            assertTrue(poll.polls > 0, "event " + k + ": the job never polled");
            assertEquals(0, poll.unheld, (t.task(k) == Timeline.PREDICT ? "predict" : "update") + " job of event " + k
                    + " polled without the robot's monitor");
            tasks[t.task(k) == Timeline.PREDICT ? 0 : 1] = true;
        }
        assertTrue(tasks[0] && tasks[1], "the input has no event of one task");
    }

    /** Never aborts; counts the polls made without the robot's monitor held. */
    private static final class MonitorAtPoll implements AbortSignal {
        private final Robot robot;
        private int polls;
        private int unheld;

        MonitorAtPoll(Robot robot) {
            this.robot = robot;
        }

        @Override
        public boolean abortRequested() {
            polls++;
            if (!Thread.holdsLock(robot)) {
                unheld++;
            }
            return false;
        }
    }

    private static boolean run(Robot robot, Timeline t, int k, AbortSignal abort) {
        return t.task(k) == Timeline.PREDICT ? robot.predict(k, abort) : robot.update(k, abort);
    }

    @Test
    void skipAdmitsOneEventAtATime() {
        JobGate g = new JobGate(OverrunPolicy.SKIP, 4);
        assertTrue(g.admit(0));
        assertFalse(g.admit(1), "the robot is reserved by event 0");
        g.release(0);
        assertTrue(g.admit(2));
        assertFalse(g.abortRequested(2), "skip never aborts");
    }

    @Test
    void terminateAbortsAllButTheLatest() {
        JobGate g = new JobGate(OverrunPolicy.TERMINATE, 4);
        assertTrue(g.admit(0));
        assertFalse(g.abortRequested(0));
        assertTrue(g.admit(1));
        assertTrue(g.abortRequested(0), "a later release aborts the job in progress");
        assertFalse(g.abortRequested(1));
    }

    @Test
    void skipDropsAPeriodicReleaseItsOwnPreviousJobOverranInto() {
        JobGate g = new JobGate(OverrunPolicy.SKIP, 4);
        assertTrue(g.admitPeriodic(0, 0));
        g.release(0);
        g.periodicEnded(60);
        assertFalse(g.admitPeriodic(1, 50), "the previous job ended at 60, after this release at 50");
        assertTrue(g.admitPeriodic(2, 100), "ended before this release: admitted");
        assertFalse(g.admit(3), "the periodic job holds the robot");
        assertEquals(Long.MAX_VALUE, g.periodicAbortAtNs(150), "skip never aborts");
    }

    /**
     * Under skip, an odometry and a laser event at one instant that the predict task's previous job
     * overran are both dropped, whichever handler decides them: the periodic handler, late behind
     * its own job, or the sensor arriving after that job freed the robot but before the periodic
     * handler's next release (the other engines' dispatcher would find the robot busy at that
     * instant; docs/RELEASE-ENGINE.md, "Events at the same time"). The sensor's decision is taken
     * inside the gate's release of the robot, the latest point at which a sensor can come first.
     */
    @Test
    void skipDropsATieThePeriodicJobOverranIntoEvenWhenTheSensorDecidesItOnceTheRobotIsFree() {
        // ms become ns: events 0 (odometry, 1 ns), 1 (odometry, 2 ns) and 2 (laser, 2 ns); any job outlasts 1 ns
        MissionConfiguration c = new MissionConfiguration(MclConfig.builder().particles(PARTICLES).build(),
                OverrunPolicy.SKIP, 1e-6);
        ImmortalEntry entry = new ImmortalEntry(new OdometryWithATie(), c);
        assertEquals(entry.releaseNs[1], entry.releaseNs[2], "events 1 and 2 are at one instant");
        SensorOnRobotRelease gate = new SensorOnRobotRelease(entry.size());
        gate.orderTies(entry.timeline, entry.releaseNs);
        Robot robot = c.newRobot(c.newLocalizer(entry.playground, entry.startX, entry.startY, entry.startTheta), entry);
        MissionClock clock = new MissionClock();
        clock.start(new AbsoluteTime());
        JobRunner predict = new JobRunner(robot, gate, entry, clock, null, null, MissionSizes.PREDICT);
        assertTrue(gate.admitPeriodic(0, entry.releaseNs[0]));
        long end = predict.run(0, false, gate.periodicAbortAtNs(entry.releaseNs[1]));
        assertTrue(end > entry.releaseNs[1], "the job of event 0 overran the instant of events 1 and 2: " + end);
        assertEquals(1, gate.sensorDecisions, "the sensor decided while the robot was being freed");
        assertFalse(gate.sensorAdmitted, "the laser event of the tie was admitted");
        assertFalse(gate.admitPeriodic(1, entry.releaseNs[1]),
                "the odometry event of the tie was admitted: the sensor decided it as if the robot had been free then");
        assertTrue(gate.admit(3), "the robot is free for the next instant");
    }

    /** Two odometry events 1 ms apart, a laser event with the second, one more laser event after. */
    private static final class OdometryWithATie extends PlacedMissionInput {
        OdometryWithATie() {
            super(2, 2, Playground.thesis(), 1.5, 1.0, 0.0);
        }

        @Override
        public void readOdometry(double[] time, double[] dx, double[] dy, double[] dtheta) {
            for (int i = 0; i < time.length; i++) {
                time[i] = 0.001 * (i + 1);
                dx[i] = 0.01;
                dtheta[i] = 0.01;
            }
        }

        @Override
        public void readLaser(double[] time, double[] angle) {
            time[0] = 0.002;
            time[1] = 0.010;
            angle[0] = 1.0;
            angle[1] = 1.1;
        }
    }

    /** A gate whose robot release of event 0 lets the laser sensor decide event 2 right after it. */
    private static final class SensorOnRobotRelease extends JobGate {
        int sensorDecisions;
        boolean sensorAdmitted;

        SensorOnRobotRelease(int events) {
            super(OverrunPolicy.SKIP, events);
        }

        @Override
        public synchronized void release(int k) {
            super.release(k);
            if (k == 0) {
                sensorDecisions++;
                sensorAdmitted = admit(2);
            }
        }
    }

    @Test
    void terminateAbortsAPeriodicJobAtItsTasksNextRelease() {
        JobGate g = new JobGate(OverrunPolicy.TERMINATE, 4);
        g.periodicEnded(60);
        assertTrue(g.admitPeriodic(1, 50), "terminate never drops a release");
        assertEquals(100, g.periodicAbortAtNs(100));
        assertEquals(Long.MAX_VALUE, g.periodicAbortAtNs(Long.MAX_VALUE), "the last release runs to its end");
    }

    @Test
    void queueRunsEveryPeriodicReleaseToItsEnd() {
        JobGate g = new JobGate(OverrunPolicy.QUEUE, 4);
        g.periodicEnded(60);
        assertTrue(g.admitPeriodic(1, 50));
        assertTrue(g.admitPeriodic(2, 55));
        assertEquals(Long.MAX_VALUE, g.periodicAbortAtNs(100));
    }

    @Test
    void queueAdmitsEverythingAndNeverAborts() {
        JobGate g = new JobGate(OverrunPolicy.QUEUE, 3);
        assertTrue(g.admit(0));
        assertTrue(g.admit(1));
        assertFalse(g.abortRequested(0));
        assertFalse(g.ended());
        assertFalse(g.ended());
        assertTrue(g.ended(), "the third of three events is the last");
    }
}
