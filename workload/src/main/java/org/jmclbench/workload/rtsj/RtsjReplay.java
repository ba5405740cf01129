package org.jmclbench.workload.rtsj;

import java.util.List;
import java.util.concurrent.locks.ReentrantLock;

import javax.realtime.AbsoluteTime;
import javax.realtime.AsyncEvent;
import javax.realtime.AsynchronouslyInterruptedException;
import javax.realtime.BoundAsyncEventHandler;
import javax.realtime.Clock;
import javax.realtime.Interruptible;
import javax.realtime.PriorityParameters;
import javax.realtime.PriorityScheduler;
import javax.realtime.RealtimeThread;

import org.jmclbench.core.mcl.AbortSignal;
import org.jmclbench.core.policy.OverrunPolicy;
import org.jmclbench.core.record.JobRecords;
import org.jmclbench.workload.RunFailure;
import org.jmclbench.workload.release.EventJob;
import org.jmclbench.workload.release.JobRecorder;
import org.jmclbench.workload.release.ReleaseSchedule;
import org.jmclbench.workload.shim.CpuClock;
import org.jmclbench.workload.shim.RuntimeShim;

/**
 * One replay of the timeline in the thesis's RTSJ structure (section 4.2.5). A dispatcher
 * {@link RealtimeThread}, above the tasks' priority, sleeps to each event's absolute release time
 * and fires its task's {@link AsyncEvent}; each task (predict, update) is a
 * {@link BoundAsyncEventHandler} whose logic takes the events released to it in order (RTSJ keeps
 * one pending fire per release). The job in progress holds the robot's {@link ReentrantLock} (the
 * thesis's), whose order, not the rule, decides which waiting job takes it next. The dispatcher
 * asks the policy's rule ({@link OverrunPolicy}) at each release (those of one instant all
 * decided, in timeline order, before any is fired): a dropped event ends there (skip: while an
 * admitted event has not ended, started or not; the thesis's {@code isLocked()} counted only
 * started jobs); an admitted one is fired; and when the job in progress has its abort requested
 * (terminate), the dispatcher fires its {@link AsynchronouslyInterruptedException}. Under a
 * policy that aborts jobs in progress the jobs run in the AIE's {@code doInterruptible}. A job the
 * rule will not start, or whose abort was requested before it started, never starts. Every event
 * ends once: done, late, skipped or terminated.
 *
 * <p>Times in the records are ns from the release of time 0, read from RTSJ's real-time clock
 * (so that Java PathFinder runs this class on virtual time). A job's abort request
 * ({@link JobRecords#abortNs}) is when its AIE was fired, so that abort latency (request to the
 * job's end) is measured: for the thesis design, the job's remaining time. Only RTSJ 1.0.2 API and the
 * {@link RuntimeShim} are used: {@code ant rtsj-engine} builds it for an RTSJ VM.
 *
 * <p>Each task records its jobs through a {@link JobRecorder}, the javase handlers' recorder, on
 * the real-time clock. A job's CPU time ({@link JobRecords#cpuNs}) is read from the shim's
 * {@link CpuClock} on the handler's thread: once its release is taken (before the doInterruptible
 * under terminate), and again when the job's event is recorded, after the robot is handed on. It so covers the job, its
 * time stamps and the hand-over, the wait for the robot (blocked: no CPU) and, for an aborted job,
 * the AIE's delivery and its unwinding to the doInterruptible's return (the abort taking hold).
 * It is -1 for a job that never started and wherever the clock is not usable (an RTSJ VM, Java
 * PathFinder, {@code --no-cpu-time}): then no clock is read.
 */
public final class RtsjReplay {
    /** The handlers are started this long before the release of time 0. */
    private static final long LEAD_NS = 20_000_000L;
    private static final String[] TASK_NAMES = {"predict", "update"};

    private final ReleaseSchedule schedule;
    private final OverrunPolicy policy;
    private final RtsjDesign design;
    private final EventJob job;
    private final JobRecords records;
    private final CpuClock cpuClock;
    /** The thesis's {@code synchronized (robot)}: the robot's monitor. */
    private final Object robot = new Object();
    /** Held by the job in progress: the thesis's test of whether a task is running. */
    private final ReentrantLock busy = new ReentrantLock();
    private final Task[] tasks = new Task[TASK_NAMES.length];
    /**
     * The policy's state: changed by the dispatcher (admit) and by an event's handler (its job's
     * end) only. Unordered: the robot's lock orders the waiting jobs.
     */
    private final OverrunPolicy.State rule;
    /** The event whose job is in its doInterruptible (a policy that aborts jobs in progress), or -1. */
    private volatile int running = -1;
    private volatile int ended;
    /** The first failure of a job or handler ("predict: ..."), or null. */
    private String failure;
    private long t0;
    /** The real-time clock minus System.nanoTime(), taken once before the replay (see {@link #clockOffset}). */
    private long nanoToClock;
    // The main thread's clock reading (each thread reads into its own AbsoluteTime: no allocation).
    private final AbsoluteTime mainClock = new AbsoluteTime();

    /**
     * A replay of {@code schedule} under {@code policy}: each released event runs {@code job} on the
     * robot, its CPU time read from {@code cpuClock} ({@link RuntimeShim#cpuClock}).
     */
    public RtsjReplay(ReleaseSchedule schedule, OverrunPolicy policy, RtsjDesign design, EventJob job, JobRecords records,
                      CpuClock cpuClock) {
        this.schedule = schedule;
        this.policy = policy;
        this.rule = new OverrunPolicy.State(policy, false);
        this.design = design;
        this.job = job;
        this.records = records;
        this.cpuClock = cpuClock;
    }

    /** A replay that reads no CPU clock (every {@code cpu_ns} -1): Java PathFinder's, which has none. */
    public RtsjReplay(ReleaseSchedule schedule, OverrunPolicy policy, RtsjDesign design, EventJob job, JobRecords records) {
        this(schedule, policy, design, job, records, RuntimeShim.noCpuClock("not measured"));
    }

    /** ns from the release of time 0 to now, on the real-time clock (the run's duration, after {@link #run}). */
    public long elapsedNs() {
        return now(mainClock) - t0;
    }

    /** The real-time clock in ns, read into the calling thread's {@code dest}. */
    private static long now(AbsoluteTime dest) {
        Clock.getRealtimeClock().getTime(dest);
        return dest.getMilliseconds() * 1_000_000L + dest.getNanoseconds();
    }

    /**
     * The real-time clock minus {@code System.nanoTime()}, from the tightest of three readings of
     * the clock between two nanoTimes: the atomic design notes a delivery in nanoTime (a clock call
     * at a delivery point costs tens of us cold), and this carries it onto the clock. Taken once,
     * before the first release: per job, a preemption between two reads moved the delivery earlier,
     * possibly before the abort it answered, and it was work inside the measured run.
     */
    private static long clockOffset(AbsoluteTime dest) {
        long spread = Long.MAX_VALUE;
        long offset = 0;
        for (int i = 0; i < 3; i++) {
            long before = System.nanoTime();
            long onClock = now(dest);
            long after = System.nanoTime();
            if (after - before < spread) {
                spread = after - before;
                offset = onClock - (before + spread / 2);
            }
        }
        return offset;
    }

    /**
     * Runs the replay to its end, then stops the handlers. A job that throws, a handler that does
     * not end, an event never accounted for or the robot's lock left held is the run's failure.
     */
    public void run(long hangNs) throws RunFailure, InterruptedException {
        int n = schedule.size();
        for (int k = 0; k < n; k++) {
            records.releaseNs[k] = schedule.releaseNs(k);
            records.deadlineNs[k] = schedule.deadlineNs(k);
            records.abortNs[k] = -1;
        }
        RuntimeShim.get().beforeReplay();
        int max = PriorityScheduler.instance().getMaxPriority();
        int[] count = new int[tasks.length];
        for (int k = 0; k < n; k++) {
            count[schedule.task(k)]++;
        }
        for (int t = 0; t < tasks.length; t++) {
            tasks[t] = new Task(TASK_NAMES[t], count[t], max - 1);
        }
        Dispatcher dispatcher = new Dispatcher();
        RealtimeThread thread = new RealtimeThread(new PriorityParameters(max), null, null, null, null, dispatcher);
        thread.setDaemon(true);
        nanoToClock = clockOffset(mainClock);
        t0 = now(mainClock) + LEAD_NS;
        for (Task task : tasks) {
            task.recorder.runStart(t0);
        }
        thread.start();
        thread.join(Math.max(1, (hangNs + LEAD_NS) / 1_000_000L));
        List<String> alive = RuntimeShim.get().endHandlers(10_000);
        if (thread.isAlive()) {
            thread.interrupt();
            throw new RunFailure("the rtsj replay did not end within " + hangNs / 1_000_000_000L + " s: " + ended
                    + " of " + n + " events ended" + (alive.isEmpty() ? "" : "; handlers still running: " + alive));
        }
        String failed = failure();
        if (failed != null) {
            throw new RunFailure("a job failed in the rtsj engine: " + failed);
        }
        if (!alive.isEmpty()) {
            throw new RunFailure("rtsj handlers did not end: " + alive);
        }
        if (busy.isLocked()) {
            throw new RunFailure("a job of the rtsj engine left the robot's lock held");
        }
        for (int k = 0; k < n; k++) {
            if (records.outcome[k] == JobRecords.PENDING) {
                throw new RunFailure("event " + k + " was never accounted for by the rtsj engine");
            }
        }
    }

    private synchronized void failed(String where, Throwable e) {
        if (failure == null) {
            failure = where + ": " + e;
        }
    }

    private synchronized String failure() {
        return failure;
    }

    /** Whether an abort of event k's job was requested (its AIE fired at it while it ran). */
    public boolean abortRequested(int k) {
        return records.abortNs[k] >= 0;
    }

    /** How many events have ended (each must end once: after {@link #run}, the schedule's size). */
    public synchronized int endedCount() {
        return ended;
    }

    private synchronized void ended() {
        ended++;
        if (ended == schedule.size()) {
            notifyAll();
        }
    }

    private synchronized void awaitEveryEvent() throws InterruptedException {
        while (ended < schedule.size()) {
            wait();
        }
    }

    /** The thesis's control thread's logic: sleeps to each release and fires the event. */
    private final class Dispatcher implements Runnable {
        private final AbsoluteTime next = new AbsoluteTime();
        private final AbsoluteTime clock = new AbsoluteTime();

        @Override
        public void run() {
            try {
                dispatch();
                awaitEveryEvent();
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            } catch (Throwable e) {
                failed("dispatcher", e);
            }
        }

        private void dispatch() throws InterruptedException {
            int n = schedule.size();
            int k = 0;
            while (k < n) {
                long at = t0 + schedule.releaseNs(k);
                next.set(at / 1_000_000L, (int) (at % 1_000_000L));
                RealtimeThread.sleep(next);
                // Events of one release instant: the policy decides each, in timeline order, before
                // any is fired, so none of them has started when the next is decided
                // (docs/RELEASE-ENGINE.md, "Events at the same time").
                int end = k + 1;
                while (end < n && schedule.releaseNs(end) == schedule.releaseNs(k)) {
                    end++;
                }
                for (int j = k; j < end; j++) {
                    admit(j);
                }
                for (int j = k; j < end; j++) {
                    if (records.outcome[j] != JobRecords.SKIPPED) {
                        Task task = tasks[schedule.task(j)];
                        task.offer(j);
                        task.event.fire();
                    }
                }
                k = end;
            }
        }

        /**
         * The policy's decision at k's release; a dropped event ends here. A job in progress whose
         * abort that release requested is fired at (a job not started yet sees the request and never starts).
         */
        private void admit(int k) {
            if (!rule.admit(k, false)) {
                records.wakeNs[k] = -1;
                records.outcome[k] = JobRecords.SKIPPED; // the robot is busy: dropped
                ended();
                return;
            }
            if (policy.abortsJobInProgress()) {
                int r = running;
                if (r >= 0 && policy.abortRequested(rule, r)) {
                    long fired = now(clock) - t0;
                    if (tasks[schedule.task(r)].aie.fire()) { // false: it ended meanwhile, nothing was asked of it
                        records.requestAbort(r, fired);
                    }
                }
            }
        }
    }

    /**
     * One task: its event, its bound handler, its AIE and the events released to it. The
     * handler's logic runs one job per release; under a policy that aborts jobs in progress inside the AIE's
     * {@code doInterruptible}, where {@link #run(AsynchronouslyInterruptedException)} is the
     * AI-enabled part (woven with delivery points) and the robot work happens in non-AI methods.
     */
    private final class Task implements Runnable, Interruptible {
        final AsyncEvent event = new AsyncEvent();
        final DeliveryPoints.WitnessedInterrupt aie = new DeliveryPoints.WitnessedInterrupt();
        private final String name;
        private final AbsoluteTime clock = new AbsoluteTime();
        private final int[] fifo;
        /** Records this task's jobs, on the real-time clock from t0; used by the handler's thread only. */
        final JobRecorder recorder;
        private volatile int head;
        private volatile int tail;
        // The job in progress, written by the handler's thread only.
        private int k;
        private boolean started;
        private boolean committed;

        Task(String name, int capacity, int priority) {
            this.name = name;
            fifo = new int[Math.max(1, capacity)];
            recorder = new JobRecorder(records, cpuClock, 0);
            event.addHandler(new BoundAsyncEventHandler(new PriorityParameters(priority), null, null, null, null,
                    false, this));
        }

        /** Dispatcher side, before the fire: the next event of this task. */
        void offer(int event) {
            fifo[tail % fifo.length] = event;
            tail = tail + 1; // volatile write publishes the slot before the fire
        }

        /**
         * One release: the oldest event released to this task. A throwable out of the job (an AIE
         * that escaped its doInterruptible included) is the run's failure, naming the task; the
         * event still ends.
         */
        @Override
        public void run() {
            int h = head;
            k = fifo[h % fifo.length];
            head = h + 1;
            records.wakeNs[k] = now(clock) - t0;
            recorder.startCpu(); // out of the AI-enabled code: no AIE can land between it and the job
            started = false;
            committed = false;
            try {
                if (policy.abortsJobInProgress()) {
                    aie.doInterruptible(this);
                } else {
                    lockAndRun(AbortSignal.NEVER, true); // no ATC where no job is aborted: no delivery point runs
                }
            } catch (Throwable e) {
                failed(name, e);
            }
            finish();
        }

        /**
         * The AI-enabled part of a terminable job. The AIE may be thrown at any delivery point
         * here (after each call, at the entry): before the job starts, at a poll of the localizer
         * (atomic), or after the robot's monitor is left (thesis: the whole job has run).
         */
        @Override
        public void run(AsynchronouslyInterruptedException interrupt) throws AsynchronouslyInterruptedException {
            running = k; // published before the rule is asked: a later release sees it and fires
            if (!mayStart()) {
                running = -1;
                return; // superseded before it started: never starts
            }
            lockAndRun(design == RtsjDesign.ATOMIC ? DeliveryPoints.INSTANCE : AbortSignal.NEVER, false);
        }

        /** Whether the rule lets k start: neither refused nor asked to abort (superseded before it started). */
        private boolean mayStart() {
            return policy.start(rule, k) != OverrunPolicy.NEVER && !policy.abortRequested(rule, k);
        }

        @Override
        public void interruptAction(AsynchronouslyInterruptedException interrupt) {
            // finish() records the outcome from what the job had done when the AIE arrived.
        }

        /**
         * Takes the robot and runs the job (non-AI: no delivery point in here but those of the
         * atomic design's signal); the lock is released whatever ends the job. The thesis design
         * holds the robot's monitor for the whole job. {@code askRule}: with no ATC (the policy
         * aborts no job in progress), the rule is asked once the robot's lock is held, as the scj
         * mission asks it holding the robot: an event it superseded while it waited never starts.
         * (Interruptible jobs ask before they wait, and a later release fires at them.)
         */
        private void lockAndRun(AbortSignal signal, boolean askRule) {
            try {
                busy.lock();
                if (askRule && !mayStart()) {
                    return; // superseded while it waited for the robot: never starts
                }
                recorder.started(now(clock));
                started = true;
                if (design == RtsjDesign.THESIS) {
                    synchronized (robot) {
                        runJob(signal);
                    }
                } else {
                    runJob(signal);
                }
            } finally {
                if (!committed && started) {
                    // an aborted job ends here, before the robot is handed on (the next job's
                    // thread may take the CPU at the unlock), as the other engines take its end
                    recorder.ended(now(clock));
                }
                running = -1;
                if (busy.isHeldByCurrentThread()) {
                    busy.unlock();
                }
                rule.ended(k); // skip: the robot is free for the next release
            }
        }

        /** The job on the robot; a completed job's end is taken before anything else can happen. */
        private void runJob(AbortSignal signal) {
            if (job.run(k, signal)) {
                recorder.ended(now(clock));
                committed = true;
            }
        }

        /** The event's record, from what the job did (an AIE may have cut it short anywhere). */
        private void finish() {
            if (!started) {
                recorder.recordNeverStarted(k); // superseded before it started
            } else {
                // The CPU clock's second read is the record's first: the robot is handed on, the
                // AIE (if any) has unwound. An aborted job's end was taken in lockAndRun.
                recorder.record(k, committed, aie.delivered ? aie.deliveredNanoTime + nanoToClock : -1);
            }
            aie.reset(); // the next job starts with no delivery noted
            ended();
        }
    }
}
