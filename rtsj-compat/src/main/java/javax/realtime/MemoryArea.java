package javax.realtime;

import javax.safetycritical.annotate.SCJAllowed;
import org.jmclbench.rtsjcompat.Area;
import org.jmclbench.rtsjcompat.RunState;
import org.jmclbench.rtsjcompat.ScjThread;

/**
 * A memory area. On Java SE an area is a budget over the garbage-collected heap: what the
 * threads allocate while it is their allocation context is measured and charged to it
 * (see {@link org.jmclbench.rtsjcompat.ScjThread}); exceeding its size raises
 * {@code OutOfMemoryError}. The bookkeeping is an {@link Area}.
 */
@SCJAllowed
public abstract class MemoryArea {
    private final Area area;

    /** The API object of {@code area}. */
    protected MemoryArea(Area area) {
        if (area == null) {
            throw new IllegalArgumentException("area is null");
        }
        this.area = area;
        area.bind(this);
    }

    /** The bookkeeping of this area (for this layer's packages). */
    protected final Area area() {
        return area;
    }

    /** The size of the area in bytes. */
    public long size() {
        return area.size();
    }

    /** The bytes the area holds (the calling thread's allocations charged first). */
    public long memoryConsumed() {
        chargeCaller();
        return area.used();
    }

    /** The bytes the area can still take. */
    public long memoryRemaining() {
        chargeCaller();
        return Math.max(0, area.size() - area.used());
    }

    private static void chargeCaller() {
        Thread t = Thread.currentThread();
        if (t instanceof ScjThread) {
            ((ScjThread) t).chargeNow();
        }
    }

    /** Runs {@code logic} with this area as the calling thread's allocation context. */
    public void executeInArea(Runnable logic) {
        if (logic == null) {
            throw new IllegalArgumentException("logic is null");
        }
        ScjThread t = ScjThread.self();
        t.enter(area);
        try {
            logic.run();
        } finally {
            t.exit();
        }
    }

    /**
     * Runs {@code logic} with this area as the calling thread's allocation context (RTSJ's
     * {@code enter}; for immortal memory the same as {@link #executeInArea(Runnable)}).
     */
    public void enter(Runnable logic) {
        executeInArea(logic);
    }

    /**
     * Whether an object in this area may refer to {@code value}: value's area must live at
     * least as long. Throws UnsupportedOperationException when value's area is unknown (see
     * {@link org.jmclbench.rtsjcompat.ObjectAreaResolver}).
     */
    public boolean mayHoldReferenceTo(Object value) {
        if (value == null) {
            return true;
        }
        Area other = RunState.current().areaOf(value);
        if (other == null) {
            throw new UnsupportedOperationException("the area of this object is not known on a JVM: " + value.getClass().getName());
        }
        return area.mayHoldReferenceTo(other);
    }

    /**
     * The area {@code object} lives in. A JVM does not record it: known for the SCJ
     * infrastructure's objects (handlers) and for what an installed
     * {@link org.jmclbench.rtsjcompat.ObjectAreaResolver} knows, else UnsupportedOperationException.
     */
    public static MemoryArea getMemoryArea(Object object) {
        if (object == null) {
            throw new IllegalArgumentException("object is null");
        }
        Area a = RunState.current().areaOf(object);
        if (a == null) {
            throw new UnsupportedOperationException("the area of this object is not known on a JVM: " + object.getClass().getName());
        }
        return a.memoryArea();
    }

    @Override
    public String toString() {
        return area.name();
    }
}
