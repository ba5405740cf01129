package javax.realtime;

import java.io.Serializable;
import javax.safetycritical.annotate.SCJAllowed;

/** Memory budgets of a schedulable: its initial area, and what it may allocate in immortal memory. */
@SCJAllowed
public class MemoryParameters implements Cloneable, Serializable {
    private static final long serialVersionUID = 1L;

    /** No limit. */
    public static final long UNLIMITED = Long.MAX_VALUE;

    private final long maxInitialArea;
    private final long maxImmortal;

    /** The given budgets in bytes. */
    public MemoryParameters(long maxInitialArea, long maxImmortal) {
        if (maxInitialArea < 0) {
            throw new IllegalArgumentException("maxInitialArea is negative: " + maxInitialArea);
        }
        if (maxImmortal < 0) {
            throw new IllegalArgumentException("maxImmortal is negative: " + maxImmortal);
        }
        this.maxInitialArea = maxInitialArea;
        this.maxImmortal = maxImmortal;
    }

    /** The size of the schedulable's own (private) memory in bytes. */
    public long getMaxInitialArea() {
        return maxInitialArea;
    }

    /** What the schedulable may allocate in immortal memory (not enforced by this layer). */
    public long getMaxImmortal() {
        return maxImmortal;
    }

    @Override
    public Object clone() {
        try {
            return super.clone();
        } catch (CloneNotSupportedException e) {
            throw new InternalError("MemoryParameters is Cloneable");
        }
    }
}
