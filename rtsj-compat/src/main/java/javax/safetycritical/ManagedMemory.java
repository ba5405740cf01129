package javax.safetycritical;

import javax.realtime.MemoryArea;
import javax.safetycritical.annotate.SCJAllowed;
import org.jmclbench.rtsjcompat.Area;
import org.jmclbench.rtsjcompat.Arguments;
import org.jmclbench.rtsjcompat.RunState;
import org.jmclbench.rtsjcompat.ScjThread;

/**
 * A memory area whose lifetime the infrastructure manages: mission memory and private
 * memories. The static methods change the calling thread's allocation context.
 */
@SCJAllowed
public abstract class ManagedMemory extends MemoryArea {

    ManagedMemory(Area area) {
        super(area);
    }

    /** The bookkeeping of this area, for this package. */
    final Area bookkeeping() {
        return area();
    }

    /**
     * Runs {@code logic} in a private memory of {@code size} bytes nested in the current
     * area, carved from the handler's backing store ({@code ScopeParameters}' maxBackingStore;
     * unlimited for the launcher's thread); it is emptied when the logic returns. Entering a
     * nested memory from the same area again reuses the same area object (no allocation
     * after the first entry).
     */
    @SCJAllowed
    public static void enterPrivateMemory(int size, Runnable logic) {
        if (logic == null) {
            throw new IllegalArgumentException("logic is null");
        }
        Arguments.nonNegative(size, "size");
        ScjThread t = ScjThread.self();
        Area parent = t.current;
        if (parent == null || parent.kind() == Area.IMMORTAL) {
            throw new IllegalStateException("enterPrivateMemory needs mission or private memory as the current area");
        }
        Area nested = t.nestedArea(parent);
        if (nested == null) {
            ScjThread.pauseAccounting();
            try {
                RunState run = RunState.current();
                nested = run.newArea(run.uniqueName(parent.name() + "/nested"), Area.NESTED, size, parent);
                new PrivateMemory(nested);
                t.addNestedArea(parent, nested);
            } finally {
                ScjThread.resumeAccounting();
            }
        }
        t.reserveBackingStore(size);
        try {
            nested.resize(size);
            t.enter(nested);
            try {
                logic.run();
            } finally {
                t.exit();
            }
        } finally {
            nested.empty();
            t.releaseBackingStore(size);
        }
    }

    /**
     * Runs {@code logic} in the area of {@code obj}, which must be on the calling thread's
     * context stack. On a JVM the area of an arbitrary object is unknown: this works for the
     * SCJ infrastructure's objects (handlers: their mission memory) and for what an installed
     * {@link org.jmclbench.rtsjcompat.ObjectAreaResolver} knows.
     */
    @SCJAllowed
    public static void executeInAreaOf(Object obj, Runnable logic) {
        if (obj == null || logic == null) {
            throw new IllegalArgumentException("obj or logic is null");
        }
        ScjThread t = ScjThread.self();
        Area a = RunState.current().areaOf(obj);
        if (a == null) {
            throw new IllegalArgumentException("the area of this object is not known on a JVM: " + obj.getClass().getName());
        }
        if (!t.onStack(a)) {
            throw new IllegalArgumentException(a.name() + " is not an allocation context of this thread");
        }
        runIn(t, a, logic);
    }

    /** Runs {@code logic} in the area enclosing the current one (private: mission memory). */
    @SCJAllowed
    public static void executeInOuterArea(Runnable logic) {
        if (logic == null) {
            throw new IllegalArgumentException("logic is null");
        }
        ScjThread t = ScjThread.self();
        Area cur = t.current;
        if (cur == null || cur.parent() == null) {
            throw new IllegalStateException("the current area has no outer area");
        }
        runIn(t, cur.parent(), logic);
    }

    private static void runIn(ScjThread t, Area a, Runnable logic) {
        t.enter(a);
        try {
            logic.run();
        } finally {
            t.exit();
        }
    }

    /** What remains of the calling thread's backing store for nested private memories. */
    @SCJAllowed
    public long getRemainingBackingStore() {
        return ScjThread.self().remainingBackingStore();
    }
}
