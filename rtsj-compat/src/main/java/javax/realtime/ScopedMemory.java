package javax.realtime;

import org.jmclbench.rtsjcompat.Area;
import org.jmclbench.rtsjcompat.RtsjRuntime;
import org.jmclbench.rtsjcompat.ScjThread;

/**
 * A scoped memory (RTSJ): an area threads {@link #enter(Runnable)}; what they allocate there is
 * charged to its budget, and it is emptied when the last thread leaves. On a JVM it is a measured
 * budget over the heap, as SCJ's areas here: exceeding the size raises
 * {@link org.jmclbench.rtsjcompat.AreaOverflowError} (an OutOfMemoryError) at the leaving
 * thread's accounting point. Its parent is immortal memory; nesting and the single-parent rule
 * are not checked.
 */
public abstract class ScopedMemory extends MemoryArea {
    private int references;

    /** A scope of {@code size} bytes named {@code kindName#n}. */
    ScopedMemory(String kindName, long size) {
        super(RtsjRuntime.newScope(kindName, size));
    }

    /**
     * Runs {@code logic} with this scope as the calling thread's allocation context; the last
     * thread to leave empties it. Called from a schedulable thread (a RealtimeThread or a handler).
     */
    @Override
    public void enter(Runnable logic) {
        if (logic == null) {
            throw new IllegalArgumentException("logic is null");
        }
        ScjThread t = ScjThread.self();
        Area a = area();
        synchronized (this) {
            references++;
        }
        t.enter(a);
        try {
            logic.run();
        } finally {
            try {
                t.exit();
            } finally {
                synchronized (this) {
                    if (--references == 0) {
                        a.empty();
                    }
                }
            }
        }
    }

    /** How many threads are in this scope now. */
    public synchronized int getReferenceCount() {
        return references;
    }
}
