package javax.realtime;

import javax.safetycritical.annotate.SCJAllowed;

/** The root of the event handlers. */
@SCJAllowed
public abstract class AsyncBaseEventHandler implements Schedulable {
    /** For subclasses. */
    protected AsyncBaseEventHandler() {
    }
}
