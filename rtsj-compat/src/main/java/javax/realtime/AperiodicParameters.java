package javax.realtime;

import javax.safetycritical.annotate.SCJAllowed;

/** Releases on demand ({@code release()}), optionally with a relative deadline. */
@SCJAllowed
public class AperiodicParameters extends ReleaseParameters {

    /** No deadline. */
    public AperiodicParameters() {
        super();
    }

    /** The given relative deadline (null: none), measured from each release. */
    public AperiodicParameters(RelativeTime deadline, AsyncEventHandler missHandler) {
        super(deadline, missHandler);
        if (deadline != null && deadline.toNanos() <= 0) {
            throw new IllegalArgumentException("the deadline must be positive");
        }
    }
}
