package javax.realtime;

import java.io.Serializable;
import org.jmclbench.rtsjcompat.Arguments;
import javax.safetycritical.annotate.SCJAllowed;

/** Memory budgets of a schedulable: its initial area, and what it may allocate in immortal memory. */
@SCJAllowed
public class MemoryParameters extends ShallowCloneable implements Cloneable, Serializable {
    private static final long serialVersionUID = 1L;

    /** No limit. */
    public static final long UNLIMITED = Long.MAX_VALUE;

    private final long maxInitialArea;
    private final long maxImmortal;

    /** The given budgets in bytes. */
    public MemoryParameters(long maxInitialArea, long maxImmortal) {
        this.maxInitialArea = Arguments.nonNegative(maxInitialArea, "maxInitialArea");
        this.maxImmortal = Arguments.nonNegative(maxImmortal, "maxImmortal");
    }

    /** The size of the schedulable's own (private) memory in bytes. */
    public long getMaxInitialArea() {
        return maxInitialArea;
    }

    /** What the schedulable may allocate in immortal memory (not enforced by this layer). */
    public long getMaxImmortal() {
        return maxImmortal;
    }
}
