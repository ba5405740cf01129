package javax.safetycritical;

import javax.safetycritical.annotate.SCJAllowed;
import org.jmclbench.rtsjcompat.Arguments;

/** The frames of a Level 0 schedule, repeated in order. */
@SCJAllowed
public final class CyclicSchedule {
    private final Frame[] frames;

    /** A schedule of these frames (copied). */
    public CyclicSchedule(Frame[] frames) {
        if (frames == null || frames.length == 0) {
            throw new IllegalArgumentException("a cyclic schedule needs at least one frame");
        }
        this.frames = Arguments.copyWithoutNulls(frames, "a frame is null");
    }

    Frame[] frames() {
        return frames;
    }
}
