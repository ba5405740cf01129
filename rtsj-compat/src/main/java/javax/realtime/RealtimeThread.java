package javax.realtime;

import java.util.concurrent.locks.LockSupport;
import org.jmclbench.rtsjcompat.Priorities;
import org.jmclbench.rtsjcompat.ScjThread;
import org.jmclbench.rtsjcompat.SystemTimeSource;
import org.jmclbench.rtsjcompat.TimeSource;

/**
 * A real-time thread (RTSJ 1.0.2): a thread at a fixed priority ({@link PriorityParameters},
 * 1 to 100, mapped onto Java priorities as for SCJ) that can sleep to an absolute time, run
 * periodically ({@link #waitForNextPeriod()} with {@link PeriodicParameters}), allocate in memory
 * areas (as an SCJ thread: {@link org.jmclbench.rtsjcompat.ScjThread}) and be the target of
 * asynchronous transfer of control ({@link AsynchronouslyInterruptedException}).
 *
 * <p>Sleeps use the real-time clock of the installed {@link TimeSource}: on system time
 * {@code System.nanoTime} and {@code LockSupport.parkNanos} re-armed from the absolute deadline;
 * on virtual time (Java PathFinder, deterministic tests) a thread running a {@code logic}
 * Runnable takes part from {@link #start()} to the end of its {@link #run()}, as an SCJ handler
 * does (a subclass that overrides {@code run()} does not: its end cannot be seen). {@link #run()}
 * begins when {@link #start()} is called; a periodic thread's release k is at (start() + the start
 * offset) + k * period.
 */
public class RealtimeThread extends ScjThread implements Schedulable {
    private static int created;

    private SchedulingParameters scheduling;
    private final ReleaseParameters release;
    private final MemoryParameters memory;
    private final MemoryArea area;
    private long firstReleaseNs;
    private long releases;
    // Counted by the time source from start() to the end of run() (virtual time's participants).
    private boolean participant;

    /** A thread at the default priority, not periodic. */
    public RealtimeThread() {
        this(null, null, null, null, null, null);
    }

    /** A thread with the given scheduling parameters. */
    public RealtimeThread(SchedulingParameters scheduling) {
        this(scheduling, null, null, null, null, null);
    }

    /** A thread with the given scheduling and release parameters. */
    public RealtimeThread(SchedulingParameters scheduling, ReleaseParameters release) {
        this(scheduling, release, null, null, null, null);
    }

    /**
     * A thread with the given parameters (null: defaults) running {@code logic} (null: its own
     * {@link #run()}), allocating in {@code area} (null: the heap) while it runs.
     */
    public RealtimeThread(SchedulingParameters scheduling, ReleaseParameters release, MemoryParameters memory,
            MemoryArea area, ProcessingGroupParameters group, Runnable logic) {
        super(logic, nextName(), Priorities.toJava(priorityOf(scheduling)));
        this.scheduling = scheduling;
        this.release = release;
        this.memory = memory;
        this.area = area;
    }

    private static synchronized String nextName() {
        return "RealtimeThread#" + (++created);
    }

    private static int priorityOf(SchedulingParameters s) {
        return s instanceof PriorityParameters ? ((PriorityParameters) s).getPriority()
                : PriorityScheduler.instance().getNormPriority();
    }

    /** The calling thread; ClassCastException when it is not a real-time thread. */
    public static RealtimeThread currentRealtimeThread() {
        return (RealtimeThread) Thread.currentThread();
    }

    /** Starts the thread; a periodic thread's release 0 is now plus the start offset. */
    @Override
    public synchronized void start() {
        long now = TimeSource.current().nanoTime();
        long offset = 0;
        if (release instanceof PeriodicParameters) {
            offset = ((PeriodicParameters) release).getStart().toNanos();
        }
        firstReleaseNs = now + offset;
        participant = !overridesRun();
        if (participant) {
            TimeSource.current().threadStarted();
        }
        super.start();
    }

    private boolean overridesRun() {
        try {
            return getClass().getMethod("run").getDeclaringClass() != RealtimeThread.class;
        } catch (NoSuchMethodException e) {
            throw new IllegalStateException(e);
        }
    }

    /** Runs the logic given at construction, with this thread's memory area as allocation context. */
    @Override
    public void run() {
        try {
            if (area != null) {
                area.enter(new Runnable() {
                    @Override
                    public void run() {
                        RealtimeThread.super.run();
                    }
                });
            } else {
                super.run();
            }
        } finally {
            if (participant) {
                TimeSource.current().threadEnded();
            }
        }
    }

    /**
     * Sleeps until {@code time}: an {@link AbsoluteTime} is an instant, a {@link RelativeTime} a
     * duration from now. Never returns early; InterruptedException when interrupted.
     */
    public static void sleep(HighResolutionTime<?> time) throws InterruptedException {
        if (time == null) {
            throw new IllegalArgumentException("time is null");
        }
        long now = clockNanos();
        sleepUntilNanos(time instanceof AbsoluteTime ? time.toNanos() : now + time.toNanos());
    }

    /** {@link #sleep(HighResolutionTime)} measured on {@code clock} (the real-time clock only). */
    public static void sleep(Clock clock, HighResolutionTime<?> time) throws InterruptedException {
        if (clock != null && clock != Clock.getRealtimeClock()) {
            throw new UnsupportedOperationException("only the real-time clock can be slept on");
        }
        sleep(time);
    }

    /**
     * Waits for the next release of a periodic thread. True when the previous release met its
     * deadline (the release parameters' deadline, by default the period); false, at once and
     * without sleeping, when it missed it (RTSJ: no miss handler).
     */
    public boolean waitForNextPeriod() {
        if (Thread.currentThread() != this) {
            throw new IllegalThreadStateException("waitForNextPeriod is called by the thread itself");
        }
        if (!(release instanceof PeriodicParameters)) {
            throw new IllegalThreadStateException("waitForNextPeriod needs PeriodicParameters");
        }
        PeriodicParameters p = (PeriodicParameters) release;
        long period = p.getPeriod().toNanos();
        long deadline = p.getDeadline() == null ? period : p.getDeadline().toNanos();
        long current = firstReleaseNs + releases * period;
        releases++;
        if (clockNanos() > current + deadline) {
            return false;
        }
        try {
            sleepUntilNanos(current + period);
        } catch (InterruptedException e) {
            super.interrupt(); // keep the status for the caller (RTSJ: wFNP is not interruptible)
        }
        return true;
    }

    /**
     * Interrupts the thread: the generic AIE becomes pending if a doInterruptible is in progress
     * (delivered at its next delivery point), and the Java interrupt status is set.
     */
    @Override
    public void interrupt() {
        AsynchronouslyInterruptedException.interruptGeneric(atc);
        super.interrupt();
    }

    /** The scheduling parameters (null: the default priority). */
    public SchedulingParameters getSchedulingParameters() {
        return scheduling;
    }

    /** Changes the priority (PriorityParameters) at once. */
    public void setSchedulingParameters(SchedulingParameters scheduling) {
        this.scheduling = scheduling;
        setPriority(Priorities.toJava(priorityOf(scheduling)));
    }

    /** The release parameters, or null. */
    public ReleaseParameters getReleaseParameters() {
        return release;
    }

    /** The memory parameters, or null. */
    public MemoryParameters getMemoryParameters() {
        return memory;
    }

    /** The memory area the thread runs in (null: the heap). */
    public MemoryArea getMemoryArea() {
        return area;
    }

    /** The calling thread's allocation context (null: the heap). */
    public static MemoryArea getCurrentMemoryArea() {
        return ScjThread.currentArea();
    }

    private static long clockNanos() {
        return TimeSource.current().nanoTime();
    }

    private static void sleepUntilNanos(long deadline) throws InterruptedException {
        TimeSource t = TimeSource.current();
        if (!(t instanceof SystemTimeSource)) {
            // Virtual time: the source's own sleep, which advances the clock when all participants wait.
            ScjThread self = ScjThread.self();
            while (!t.sleepUntil(self, deadline)) {
                if (Thread.interrupted()) {
                    throw new InterruptedException("sleep interrupted");
                }
            }
            return;
        }
        while (true) {
            if (Thread.interrupted()) {
                throw new InterruptedException("sleep interrupted");
            }
            long left = deadline - clockNanos();
            if (left <= 0) {
                return;
            }
            LockSupport.parkNanos(left);
        }
    }
}
