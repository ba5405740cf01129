package javax.realtime;

import javax.safetycritical.annotate.SCJAllowed;

/**
 * An event handler permanently bound to its own thread (RTSJ): no dispatching through a pool,
 * so a release starts with the least latency. Every SCJ handler is one too.
 */
@SCJAllowed
public class BoundAsyncEventHandler extends AsyncEventHandler implements BoundAbstractAsyncEventHandler {

    /** A bound handler whose {@link #handleAsyncEvent()} is overridden. */
    public BoundAsyncEventHandler() {
        super();
    }

    /**
     * A bound handler with the given parameters running {@code logic} at each release (see
     * {@link AsyncEventHandler#AsyncEventHandler(SchedulingParameters, ReleaseParameters,
     * MemoryParameters, MemoryArea, ProcessingGroupParameters, boolean, Runnable)}).
     */
    public BoundAsyncEventHandler(SchedulingParameters scheduling, ReleaseParameters release, MemoryParameters memory,
            MemoryArea area, ProcessingGroupParameters group, boolean nonheap, Runnable logic) {
        super(scheduling, release, memory, area, group, nonheap, logic);
    }
}
