package javax.safetycritical;

import javax.safetycritical.annotate.SCJAllowed;
import org.jmclbench.rtsjcompat.Area;

/** The memory of one mission: its handlers and what they share; emptied when the mission ends. */
@SCJAllowed
public final class MissionMemory extends ManagedMemory {
    MissionMemory(Area area) {
        super(area);
    }
}
