package org.jmclbench.core.policy;

/**
 * What happens to an event released while a job works on the robot (SPEC section 4): the one
 * definition of the policies and of their rule, shared by every Java module. Each engine keeps
 * only its mechanics (how a job waits for the robot, how it is aborted) and asks the rule the
 * same questions through a per-replay {@link State}: the Java SE engine's {@code PolicyGate},
 * the SCJ mission's {@code JobGate} (also on the HVM) and the rtsj engine's {@code RtsjReplay}.
 * The HVM run file, the matrix and verification use the labels and codes; the C baseline keeps
 * the same codes in {@code native/src/policy.h}.
 *
 * <p>The questions, per event k in release order:
 * <ul>
 *   <li>at k's release, {@link State#admit(int, boolean)}: admit or drop, and
 *       {@link State#superseded()}: the event whose job that release asks to abort;</li>
 *   <li>when k's job would take the robot, {@link #start(State, int)}: now, wait, or never;</li>
 *   <li>while it runs, {@link #abortRequested(State, int)} (the job's poll);</li>
 *   <li>when it has ended, completed or not, {@link State#ended(int)};</li>
 *   <li>and of the policy itself: {@link #abortsJobInProgress()} (a release aborts the job in
 *       progress: the rtsj engine runs jobs interruptible, the SCJ periodic job stops at its
 *       task's next release) and {@link #eventsWait()} (an admitted event may wait for the
 *       robot: the Java SE engine wakes waiters when a job ends).</li>
 * </ul>
 * The two a job asks about itself ({@code start}, {@code abortRequested}) read only volatile
 * fields: lock-free and allocation-free, polled inside the job. The ones that change the state
 * ({@code admit}, {@code ended}) are called under the engine's lock (the SCJ gate's monitor), or
 * without one where the engine keeps to their threads: admit by one dispatcher thread, ended(k)
 * by k's handler (the fields two threads meet at are volatile).
 *
 * <p>A new policy is one constant here with its {@code admit} and what it changes of the defaults
 * (never start, abort, hand the robot in order, its missCount), a new code in {@link #ofCode} and {@link #ofLabel},
 * and its tests; the engines need no edit. Job code looks a policy up with {@link #ofCode(long)}
 * or {@link #ofLabel(String)}, never {@code values()}, which allocates a copy on every call.
 */
public enum OverrunPolicy {
    /** The new event is dropped (the thesis's SkipTest). */
    SKIP(0, "skip", "SkipTest") {
        /**
         * Dropped while an admitted event has not ended, started or not, or while the engine judged
         * the robot busy; else k reserves the robot from its release to its job's end.
         */
        @Override
        boolean admit(State s, int k, boolean robotBusy) {
            if (robotBusy || s.reserved != State.FREE) {
                return false;
            }
            s.reserved = k;
            return true;
        }

        @Override
        void ended(State s, int k) {
            if (s.reserved == k) {
                s.reserved = State.FREE;
            }
        }

        /** One admitted event at a time: none ever waits for the robot. */
        @Override
        public boolean eventsWait() {
            return false;
        }
    },
    /** The job in progress is asked to abort, polled every poll interval, and the new event runs (TermTest). */
    TERMINATE(1, "terminate", "TermTest") {
        /** Only the latest released event may run: the previous latest is superseded. */
        @Override
        boolean admit(State s, int k, boolean robotBusy) {
            s.superseded = s.latest;
            s.latest = k; // the job in progress sees this at its next poll and aborts
            return true;
        }

        /** Superseded: a later event was released. A job asked before it started never starts. */
        @Override
        public boolean abortRequested(State s, int k) {
            return s.latest != k;
        }

        @Override
        public boolean abortsJobInProgress() {
            return true;
        }
    },
    /** Every event is processed in release order; one completed after its deadline is late (QueueTest). */
    QUEUE(2, "queue", "QueueTest") {
        @Override
        boolean admit(State s, int k, boolean robotBusy) {
            return true;
        }

        /** In an ordered state, k waits for k - 1 to end; else the engine's robot lock orders the jobs. */
        @Override
        public int start(State s, int k) {
            return s.ordered && s.turn != k ? WAIT : START;
        }

        @Override
        void ended(State s, int k) {
            if (s.ordered) {
                s.turn = k + 1;
            }
        }

        /** Queue drops nothing: a miss is a completion after the deadline. */
        @Override
        public int missCount(int late, int skipped, int terminated) {
            return late;
        }
    };

    /** {@link #start}: the job may take the robot now (if the engine's robot is free). */
    public static final int START = 0;
    /** {@link #start}: not yet; asked again when a job ends (only from an ordered {@link State}). */
    public static final int WAIT = 1;
    /** {@link #start}: never (superseded before it started: terminated). */
    public static final int NEVER = 2;

    /** The stable code of files and protocols (the HVM run file, the C baseline's {@code jm_policy}). */
    public final int code;
    /** The option value ({@code --policy}) and summary.json name. */
    public final String label;
    /** The thesis's test name: the run path's folder and the label of its charts. */
    public final String folder;

    OverrunPolicy(int code, String label, String folder) {
        this.code = code;
        this.label = label;
        this.folder = folder;
    }

    /**
     * At k's release: true admits k, false drops it (skipped). {@code robotBusy}: the engine judged
     * the robot busy at this release beyond what the state knows (the SCJ periodic task's previous
     * job overran into it). May set {@code s.superseded}. Called through {@link State#admit}.
     */
    abstract boolean admit(State s, int k, boolean robotBusy);

    /**
     * Whether admitted event k may take the robot now ({@link #START}), must wait ({@link #WAIT}),
     * or never starts ({@link #NEVER}). A job whose {@link #abortRequested} is true when it would
     * start never starts either. Lock-free. By default: now.
     */
    public int start(State s, int k) {
        return START;
    }

    /** Polled by k's job: true asks it to stop and leave the robot unchanged. Lock-free. By default: never. */
    public boolean abortRequested(State s, int k) {
        return false;
    }

    /** k's job has ended (see {@link State#ended}). By default nothing changes. */
    void ended(State s, int k) {
    }

    /**
     * Whether a release asks the job in progress to abort (a job's abort may be requested while it
     * runs; the SCJ periodic job stops at its task's next release). By default: no.
     */
    public boolean abortsJobInProgress() {
        return false;
    }

    /**
     * The thesis's missCount of a real-time run's jobs under this policy, from their outcomes: by
     * default the events it dropped or aborted (its test counted those, not lateness).
     */
    public int missCount(int late, int skipped, int terminated) {
        return skipped + terminated;
    }

    /** Whether an admitted event may wait for the robot while another job holds it. By default: yes. */
    public boolean eventsWait() {
        return true;
    }

    /** The policy of a code, or null when no policy has it. */
    public static OverrunPolicy ofCode(long code) {
        if (code == SKIP.code) {
            return SKIP;
        }
        if (code == TERMINATE.code) {
            return TERMINATE;
        }
        if (code == QUEUE.code) {
            return QUEUE;
        }
        return null;
    }

    /** The policy of an option value ({@code skip}, {@code terminate}, {@code queue}), or null. */
    public static OverrunPolicy ofLabel(String label) {
        if (SKIP.label.equals(label)) {
            return SKIP;
        }
        if (TERMINATE.label.equals(label)) {
            return TERMINATE;
        }
        if (QUEUE.label.equals(label)) {
            return QUEUE;
        }
        return null;
    }

    /**
     * One replay's state of its policy's rule: the engine makes one (in SCJ, in mission memory)
     * and asks the policy through it. Allocation-free after construction; no locks of its own.
     */
    public static final class State {
        /** No event. */
        public static final int FREE = -1;

        final OverrunPolicy policy;
        /**
         * Whether the rule hands the robot over in release order (queue: event k after k - 1 has
         * ended), for an engine that can wait for it (the Java SE engine parks); else the engine's
         * robot lock orders the waiting jobs (SCJ Level 1 has no wait/notify; the rtsj engine keeps
         * the thesis's lock).
         */
        final boolean ordered;
        // skip: the admitted event that holds the robot from its release to its job's end
        volatile int reserved = FREE;
        // terminate: the latest released event, the only one that may run; read by the polls
        volatile int latest = FREE;
        // queue, ordered: the event whose turn it is to take the robot
        volatile int turn;
        // the event the last admit superseded; the admitting thread's
        int superseded = FREE;

        public State(OverrunPolicy policy, boolean ordered) {
            this.policy = policy;
            this.ordered = ordered;
        }

        /** The policy. */
        public OverrunPolicy policy() {
            return policy;
        }

        /** At k's release: true admits k, false drops it; see {@link OverrunPolicy}'s locking. */
        public boolean admit(int k, boolean robotBusy) {
            superseded = FREE;
            boolean admitted = policy.admit(this, k, robotBusy);
            return admitted;
        }

        /** The event whose job the last {@link #admit} asked to abort (running, waiting or already ended), or FREE. */
        public int superseded() {
            return superseded;
        }

        /**
         * k's job has ended, completed or aborted; an engine may also call it for an event that never
         * started (the rule must accept both).
         */
        public void ended(int k) {
            policy.ended(this, k);
        }
    }
}
