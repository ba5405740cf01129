package javax.realtime;

import javax.safetycritical.annotate.SCJAllowed;

/** A handler whose {@link #handleAsyncEvent()} runs once per release. */
@SCJAllowed
public class AsyncEventHandler extends AsyncBaseEventHandler {

    /** Runs one release (the infrastructure's entry point). */
    @Override
    public final void run() {
        handleAsyncEvent();
    }

    /** The work of one release; the default does nothing. */
    public void handleAsyncEvent() {
    }
}
