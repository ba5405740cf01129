package javax.realtime;

import javax.safetycritical.annotate.SCJAllowed;
import org.jmclbench.rtsjcompat.HandlerServer;
import org.jmclbench.rtsjcompat.Priorities;

/**
 * A handler released by the {@link AsyncEvent}s it is attached to (RTSJ 1.0.2). Each fire adds
 * one to the pending fire count; the handler's thread of control runs {@link #run()}, which calls
 * {@link #handleAsyncEvent()} once per pending fire, in order (a FIFO of releases). By default
 * {@link #handleAsyncEvent()} runs the {@code logic} given at construction.
 *
 * <p>SCJ handlers ({@code javax.safetycritical.ManagedEventHandler}) extend this class through
 * the no-argument constructor and are released by the SCJ runtime instead: such a handler never
 * gets a thread here. An RTSJ handler's thread is created when the handler is first attached to
 * an event ({@link AsyncEvent#addHandler}); see {@link org.jmclbench.rtsjcompat.HandlerServer}.
 */
@SCJAllowed
public class AsyncEventHandler extends AsyncBaseEventHandler {
    private static int created;

    // The RTSJ parameters and the thread of control, in one object: an SCJ handler (built with the
    // no-argument constructor and never attached to an event) shares UNBOUND, which holds neither;
    // bind() replaces it, so UNBOUND never gets a server.
    private static final Binding UNBOUND = new Binding(null, null, null, null, null);

    private Binding binding = UNBOUND;

    /** A handler whose {@link #handleAsyncEvent()} is overridden; default scheduling, no area. */
    public AsyncEventHandler() {
    }

    /** A handler running {@code logic} at each release. */
    public AsyncEventHandler(Runnable logic) {
        this(null, null, null, null, null, false, logic);
    }

    /** A handler with the given parameters (null: defaults); {@code nonheap} has no meaning on a JVM. */
    public AsyncEventHandler(SchedulingParameters scheduling, ReleaseParameters release, MemoryParameters memory,
            MemoryArea area, ProcessingGroupParameters group, boolean nonheap) {
        this(scheduling, release, memory, area, group, nonheap, null);
    }

    /**
     * A handler with the given parameters running {@code logic} at each release; each release runs
     * with {@code area} (if not null) as its allocation context.
     */
    public AsyncEventHandler(SchedulingParameters scheduling, ReleaseParameters release, MemoryParameters memory,
            MemoryArea area, ProcessingGroupParameters group, boolean nonheap, Runnable logic) {
        binding = new Binding(scheduling, release, memory, area, logic);
    }

    /**
     * Handles the pending fires: one {@link #handleAsyncEvent()} per fire, in order, until the
     * count is zero (the handler may consume several itself with {@link #getAndClearPendingFireCount()}).
     */
    @Override
    public final void run() {
        while (getAndDecrementPendingFireCount() > 0) {
            handleAsyncEvent();
        }
    }

    /** The work of one release: runs the logic given at construction, if any. */
    public void handleAsyncEvent() {
        Runnable logic = binding().logic;
        if (logic != null) {
            logic.run();
        }
    }

    /** The number of fires not handled yet. */
    public final int getPendingFireCount() {
        HandlerServer s = server();
        return s == null ? 0 : s.pending();
    }

    /** Returns the pending fire count and sets it to zero. */
    protected final int getAndClearPendingFireCount() {
        HandlerServer s = server();
        return s == null ? 0 : s.getAndClear();
    }

    /** Returns the pending fire count and decrements it when positive. */
    protected final int getAndDecrementPendingFireCount() {
        HandlerServer s = server();
        return s == null ? 0 : s.getAndDecrement();
    }

    /** Returns the pending fire count and increments it (a release without an event, handled in turn). */
    protected final int getAndIncrementPendingFireCount() {
        return bind().getAndIncrement();
    }

    /** The scheduling parameters (null: the default priority). */
    public SchedulingParameters getSchedulingParameters() {
        return binding().scheduling;
    }

    /** The release parameters given at construction, or null. */
    public ReleaseParameters getReleaseParameters() {
        return binding().release;
    }

    /** The memory parameters given at construction, or null. */
    public MemoryParameters getMemoryParameters() {
        return binding().memory;
    }

    /** The allocation context of each release (null: the heap). */
    public MemoryArea getMemoryArea() {
        return binding().area;
    }

    /** One fire of an event this handler is attached to. */
    final void fired() {
        bind().fire();
    }

    /** The handler's thread of control, created (with its name, class#n) if it has none yet. */
    final synchronized HandlerServer bind() {
        if (binding == UNBOUND) {
            binding = new Binding(null, null, null, null, null);
        }
        if (binding.server == null) {
            SchedulingParameters sp = binding.scheduling;
            int p = sp instanceof PriorityParameters ? ((PriorityParameters) sp).getPriority()
                    : PriorityScheduler.instance().getNormPriority();
            int n;
            synchronized (AsyncEventHandler.class) {
                n = ++created;
            }
            binding.server = new HandlerServer(this, getClass().getSimpleName() + "#" + n, Priorities.toJava(p),
                    binding.area);
        }
        return binding.server;
    }

    private synchronized Binding binding() {
        return binding;
    }

    private synchronized HandlerServer server() {
        return binding.server;
    }

    /** A handler's RTSJ parameters and its thread of control. */
    private static final class Binding {
        final SchedulingParameters scheduling;
        final ReleaseParameters release;
        final MemoryParameters memory;
        final MemoryArea area;
        final Runnable logic;
        HandlerServer server;

        Binding(SchedulingParameters scheduling, ReleaseParameters release, MemoryParameters memory, MemoryArea area,
                Runnable logic) {
            this.scheduling = scheduling;
            this.release = release;
            this.memory = memory;
            this.area = area;
            this.logic = logic;
        }
    }
}
