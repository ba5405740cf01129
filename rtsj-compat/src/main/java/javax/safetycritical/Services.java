package javax.safetycritical;

import javax.safetycritical.annotate.Level;
import javax.safetycritical.annotate.SCJAllowed;
import org.jmclbench.rtsjcompat.Area;
import org.jmclbench.rtsjcompat.Priorities;
import org.jmclbench.rtsjcompat.RunState;
import org.jmclbench.rtsjcompat.ScjThread;

/** Services of the infrastructure. */
@SCJAllowed
public class Services {

    /** Not instantiated by applications. */
    protected Services() {
    }

    /** The level the application was launched at. */
    @SCJAllowed
    public static Level getComplianceLevel() {
        return RunState.current().level() == 0 ? Level.LEVEL_0 : Level.LEVEL_1;
    }

    /** The ceiling of a monitor with none set: the highest priority. */
    @SCJAllowed(Level.LEVEL_1)
    public static int getDefaultCeiling() {
        return Priorities.MAX;
    }

    /**
     * Sets the priority ceiling of {@code target}'s monitor. Checked but not emulated: on a
     * JVM a synchronized method does not raise its caller to the ceiling (see the README).
     */
    @SCJAllowed(Level.LEVEL_1)
    public static void setCeiling(Object target, int ceiling) {
        if (target == null) {
            throw new IllegalArgumentException("target is null");
        }
        if (ceiling < Priorities.MIN || ceiling > Priorities.MAX) {
            throw new IllegalArgumentException("ceiling outside " + Priorities.MIN + ".." + Priorities.MAX + ": " + ceiling);
        }
    }

    /** The name of the calling thread's current area, or null outside SCJ code. */
    public static String getNameOfCurrentMemoryArea() {
        Area a = ScjThread.currentAllocationArea();
        return a == null ? null : a.name();
    }
}
