package org.jmclbench.rtsjcompat;

import javax.realtime.MemoryArea;

/**
 * The thread of control of one RTSJ event handler and its pending fire count: each fire
 * increments the count and wakes the thread, which runs the handler's {@code run()} (RTSJ: handle
 * every pending fire, one {@code handleAsyncEvent} each, in order) with the handler's memory area
 * as its allocation context, until the count is zero; then it waits for the next fire.
 *
 * <p>On this layer every handler is bound to its own server thread (for a
 * {@code BoundAsyncEventHandler} that is RTSJ's rule; an unbound handler gets one too), created
 * when the handler is first attached to an event, so never in a measured window. A throwable
 * escaping the handler is recorded in {@link RtsjRuntime#failure()} and the handler goes on
 * serving. Fire, count and wake-up allocate nothing. The server takes part in the installed
 * {@link TimeSource} (started, idle while it waits for a fire, ended), so that virtual time
 * advances only when every handler waits.
 */
public final class HandlerServer extends IdleParticipant implements Runnable {
    private final Runnable handler;
    private final MemoryArea area;
    private final ScjThread thread;
    private int fireCount;
    private long fires;
    private boolean stopped;

    /** Starts the server of {@code handler} (its {@code run()} handles the pending fires) at the given Java priority. */
    public HandlerServer(Runnable handler, String name, int javaPriority, MemoryArea area) {
        super(TimeSource.current());
        this.handler = handler;
        this.area = area;
        this.thread = new ScjThread(this, name, javaPriority);
        RtsjRuntime.register(this);
        time.threadStarted();
        thread.start();
    }

    /** The server thread's name (the handler's name in failures and reports). */
    public String name() {
        return thread.getName();
    }

    /** The server thread. */
    public Thread thread() {
        return thread;
    }

    /** One fire: counted and handled in order after the ones already pending. */
    public synchronized void fire() {
        if (stopped) {
            return;
        }
        fireCount++;
        fires++;
        leaveIdle();
    }

    /** All fires so far. */
    public synchronized long fires() {
        return fires;
    }

    /** The pending fire count. */
    public synchronized int pending() {
        return fireCount;
    }

    /** Returns the pending count and sets it to zero. */
    public synchronized int getAndClear() {
        int c = fireCount;
        fireCount = 0;
        return c;
    }

    /** Returns the pending count and decrements it if it was positive. */
    public synchronized int getAndDecrement() {
        int c = fireCount;
        if (c > 0) {
            fireCount = c - 1;
        }
        return c;
    }

    /** Returns the pending count and increments it. */
    public synchronized int getAndIncrement() {
        int c = fireCount;
        fireCount = c + 1;
        leaveIdle();
        return c;
    }

    @Override
    public void run() {
        try {
            while (awaitFire()) {
                try {
                    if (area != null) {
                        area.enter(handler);
                    } else {
                        handler.run();
                    }
                } catch (Throwable t) {
                    RtsjRuntime.fail(name(), t);
                }
            }
        } finally {
            time.threadEnded();
        }
    }

    private synchronized boolean awaitFire() {
        // An interrupt is for the handler's code, not for the server: it keeps waiting.
        while (fireCount == 0 && !stopped) {
            idleWait();
        }
        return fireCount > 0 || !stopped;
    }

    /** Ends the server once the fires pending now are handled; later fires are ignored. */
    public synchronized void stop() {
        stopped = true;
        leaveIdle();
    }
}
