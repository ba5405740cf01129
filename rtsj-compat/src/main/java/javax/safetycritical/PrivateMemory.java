package javax.safetycritical;

import javax.safetycritical.annotate.SCJAllowed;
import org.jmclbench.rtsjcompat.Area;

/** A handler's memory for one release (or a nested one from enterPrivateMemory); emptied when it ends. */
@SCJAllowed
public final class PrivateMemory extends ManagedMemory {
    PrivateMemory(Area area) {
        super(area);
    }
}
