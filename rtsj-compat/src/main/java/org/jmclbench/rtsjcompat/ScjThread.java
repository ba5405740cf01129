package org.jmclbench.rtsjcompat;

import javax.realtime.MemoryArea;

/**
 * A thread that runs SCJ code (the launcher with the Safelet and the mission sequencer,
 * each handler) and carries its allocation context: a stack of {@link Area}s whose top,
 * the field {@link #current}, receives what the thread allocates.
 *
 * <p>Accounting: at every change of context (enter, exit, end of a release) the thread reads
 * its allocation counter ({@link AllocationMeter}) and charges the bytes allocated since the
 * previous reading to the area that was current, then checks that area's budget and throws
 * {@link AreaOverflowError} in this thread if it is exceeded. Between such points nothing is
 * checked: an overflow is detected at the next one. The bookkeeping allocates nothing: the
 * stack is preallocated ({@link #MAX_DEPTH} levels), the counters are primitive.
 *
 * <p>Seam for a verification listener (Java PathFinder): the allocation context of a thread
 * is {@code ((ScjThread) t).current} (null outside SCJ code, and for a handler between its
 * releases); {@link #currentArea()} returns it for the calling thread. Each {@link Area} has a
 * stable name and a depth (immortal 0 &lt; mission 1 &lt; private 2 &lt; nested 3+).
 */
public class ScjThread extends Thread {
    /** The deepest allocation-context stack a thread may have. */
    public static final int MAX_DEPTH = 16;

    /**
     * Whether the layer's threads are daemons ({@code -Djmclbench.scj.daemon}, default true: a
     * hung mission does not keep the JVM alive). Java PathFinder's runs say false: JPF switches
     * to another thread at a thread's end only when a non-daemon one can run.
     */
    static final boolean DAEMON = Boolean.parseBoolean(System.getProperty("jmclbench.scj.daemon", "true"));

    /** The area receiving this thread's allocations now, or null (nothing is charged). */
    public Area current;

    /** The name of {@link #current}, for a verification listener reading it from Java PathFinder's heap. */
    public static final String CURRENT_FIELD = "current";

    /** This thread's side of asynchronous transfer of control (RTSJ's AIE; unused by SCJ code). */
    public final AtcState atc = new AtcState(this);

    private final Area[] stack = new Area[MAX_DEPTH];
    private int top = -1;
    private final AllocationMeter meter;
    private final long selfCost;
    private long mark;
    private int paused;

    private final Area[] nestedParents = new Area[MAX_DEPTH];
    private final Area[] nestedAreas = new Area[MAX_DEPTH];
    private long backingStore = Long.MAX_VALUE;
    private long backingUsed;

    // Used by the time sources only.
    volatile boolean wakeRequested;
    long sleepDeadline;

    /**
     * Waits until {@code t} (null: none) has terminated, through interrupts; returns whether the
     * caller was interrupted meanwhile, for it to re-assert once it has awaited all it waits for.
     */
    public static boolean joinThroughInterrupts(Thread t) {
        boolean interrupted = false;
        while (t != null && t.isAlive()) {
            try {
                t.join();
            } catch (InterruptedException e) {
                interrupted = true;
            }
        }
        return interrupted;
    }

    /** A thread running {@code body}, named {@code name}, at Java priority {@code javaPriority}. */
    public ScjThread(Runnable body, String name, int javaPriority) {
        super(null, body, name);
        this.meter = AllocationMeter.current();
        this.selfCost = meter.selfCost();
        setPriority(javaPriority);
        setDaemon(DAEMON);
    }

    /** The calling thread's current area as an API object, or null outside SCJ code. */
    public static MemoryArea currentArea() {
        Area a = currentAllocationArea();
        return a == null ? null : a.memoryArea();
    }

    /** The calling thread's current area, or null outside SCJ code. */
    public static Area currentAllocationArea() {
        Thread t = Thread.currentThread();
        return t instanceof ScjThread ? ((ScjThread) t).current : null;
    }

    /** The calling thread as an ScjThread; IllegalStateException outside SCJ code. */
    public static ScjThread self() {
        Thread t = Thread.currentThread();
        if (!(t instanceof ScjThread)) {
            throw new IllegalStateException("not called from an SCJ thread (a handler, the mission sequencer or the launcher)");
        }
        return (ScjThread) t;
    }

    /** The backing store for nested private memories (a handler's ScopeParameters). */
    public void setBackingStore(long bytes) {
        this.backingStore = bytes;
    }

    /** What remains of the backing store for nested private memories. */
    public long remainingBackingStore() {
        return backingStore - backingUsed;
    }

    /** Makes {@code area} current (the previous current area is charged first). */
    public void enter(Area area) {
        if (top + 1 >= MAX_DEPTH) {
            throw new IllegalStateException("allocation contexts nested deeper than " + MAX_DEPTH);
        }
        account();
        stack[++top] = area;
        current = area;
    }

    /** Leaves the current area (charging it and checking its budget) and returns to the one below. */
    public void exit() {
        if (top < 0) {
            throw new IllegalStateException("no allocation context to exit");
        }
        try {
            account();
        } finally {
            stack[top--] = null;
            current = top < 0 ? null : stack[top];
        }
    }

    /** Charges the current area with what this thread allocated since the last reading. */
    public void chargeNow() {
        account();
    }

    /** Whether {@code area} is on this thread's context stack. */
    public boolean onStack(Area area) {
        for (int i = 0; i <= top; i++) {
            if (stack[i] == area) {
                return true;
            }
        }
        return false;
    }

    private void account() {
        long now = meter.allocatedBytes();
        Area a = current;
        if (a != null && paused == 0) {
            long delta = now - mark - selfCost;
            if (delta > 0) {
                long held = a.charge(delta);
                mark = now;
                if (held > a.size() && a.enforced()) {
                    throw a.overflow(held);
                }
            }
        }
        mark = now;
    }

    /**
     * Stops charging the calling thread's allocations (the runtime's own objects: areas,
     * threads, lists); the area that was current is charged up to here first.
     */
    public static void pauseAccounting() {
        Thread t = Thread.currentThread();
        if (t instanceof ScjThread) {
            ScjThread s = (ScjThread) t;
            if (s.paused == 0) {
                s.account();
            }
            s.paused++;
        }
    }

    /** Resumes charging after {@link #pauseAccounting()}. */
    public static void resumeAccounting() {
        Thread t = Thread.currentThread();
        if (t instanceof ScjThread) {
            ScjThread s = (ScjThread) t;
            if (--s.paused == 0) {
                s.mark = s.meter.allocatedBytes();
            }
        }
    }

    /** The nested private memory this thread reuses for entries from {@code parent}, or null. */
    public Area nestedArea(Area parent) {
        for (int i = 0; i < MAX_DEPTH; i++) {
            if (nestedParents[i] == parent) {
                return nestedAreas[i];
            }
        }
        return null;
    }

    /** Remembers {@code nested} as the area for entries from {@code parent}. */
    public void addNestedArea(Area parent, Area nested) {
        for (int i = 0; i < MAX_DEPTH; i++) {
            if (nestedParents[i] == null) {
                nestedParents[i] = parent;
                nestedAreas[i] = nested;
                return;
            }
        }
        throw new IllegalStateException("more than " + MAX_DEPTH + " distinct nested private memories in " + getName());
    }

    /** Takes {@code size} bytes of the backing store, or throws the overflow of the backing store. */
    public void reserveBackingStore(long size) {
        if (size > remainingBackingStore()) {
            throw new AreaOverflowError("backing store of " + getName(), remainingBackingStore(), size);
        }
        backingUsed += size;
    }

    /** Gives back what {@link #reserveBackingStore(long)} took. */
    public void releaseBackingStore(long size) {
        backingUsed -= size;
    }
}
