package javax.realtime;

import javax.safetycritical.annotate.SCJAllowed;
import org.jmclbench.rtsjcompat.Area;
import org.jmclbench.rtsjcompat.RtsjRuntime;
import org.jmclbench.rtsjcompat.RunState;

/**
 * The area that lives as long as the application. In an SCJ launch its size is the Safelet's
 * {@code immortalMemorySize()}; for RTSJ code outside a launch it is measured, not bounded.
 */
@SCJAllowed
public final class ImmortalMemory extends MemoryArea {

    private ImmortalMemory(Area area) {
        super(area);
    }

    /** The immortal memory of the application running. */
    public static ImmortalMemory instance() {
        RunState run = RunState.currentOrNull();
        Area a = run == null ? RtsjRuntime.immortal() : run.immortal();
        if (a == null) {
            throw new IllegalStateException("immortal memory does not exist before the launcher created it");
        }
        synchronized (a) {
            if (a.memoryArea() == null) {
                new ImmortalMemory(a);
            }
            return (ImmortalMemory) a.memoryArea();
        }
    }
}
