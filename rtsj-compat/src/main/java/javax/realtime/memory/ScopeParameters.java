package javax.realtime.memory;

import javax.realtime.MemoryParameters;
import javax.safetycritical.annotate.SCJAllowed;
import org.jmclbench.rtsjcompat.Arguments;

/**
 * Memory budgets of an SCJ schedulable: its private memory ({@code maxInitialArea}), and
 * the backing store from which its nested private memories are carved.
 */
@SCJAllowed
public final class ScopeParameters extends MemoryParameters {
    private static final long serialVersionUID = 1L;

    private final long maxContainingArea;
    private final long maxBackingStore;

    /** The given budgets in bytes. */
    public ScopeParameters(long maxInitialArea, long maxImmortal, long maxContainingArea, long maxInitialBackingStore) {
        super(maxInitialArea, maxImmortal);
        this.maxContainingArea = Arguments.nonNegative(maxContainingArea, "maxContainingArea");
        this.maxBackingStore = Arguments.nonNegative(maxInitialBackingStore, "maxInitialBackingStore");
    }

    /** The given budgets, with no limit on the containing area. */
    public ScopeParameters(long maxInitialArea, long maxImmortal, long maxInitialBackingStore) {
        this(maxInitialArea, maxImmortal, UNLIMITED, maxInitialBackingStore);
    }

    /** What the schedulable may allocate in its containing (mission) memory (not enforced). */
    public long getMaxContainingArea() {
        return maxContainingArea;
    }

    /** The backing store for nested private memories, in bytes. */
    public long getMaxBackingStore() {
        return maxBackingStore;
    }
}
