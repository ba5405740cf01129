package javax.realtime;

import javax.safetycritical.annotate.SCJAllowed;

/** An event handler with its own thread: every SCJ handler is one. */
@SCJAllowed
public class BoundAsyncEventHandler extends AsyncEventHandler implements BoundAbstractAsyncEventHandler {
}
