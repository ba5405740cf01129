package javax.realtime;

/**
 * An event (RTSJ 1.0.2): {@link #fire()} releases every handler attached to it, each of which
 * counts the fire and handles it after the fires already pending. Attaching is done before the
 * measured window (it may allocate); {@link #fire()} allocates nothing.
 */
public class AsyncEvent {
    private AsyncEventHandler[] handlers = new AsyncEventHandler[0];

    /** An event with no handler. */
    public AsyncEvent() {
    }

    /** Attaches {@code handler} (once; attaching it again does nothing) and gives it its thread. */
    public synchronized void addHandler(AsyncEventHandler handler) {
        if (handler == null) {
            throw new IllegalArgumentException("handler is null");
        }
        if (handledBy(handler)) {
            return;
        }
        handler.bind();
        AsyncEventHandler[] h = new AsyncEventHandler[handlers.length + 1];
        System.arraycopy(handlers, 0, h, 0, handlers.length);
        h[handlers.length] = handler;
        handlers = h;
    }

    /** Detaches {@code handler} (nothing if it is not attached). */
    public synchronized void removeHandler(AsyncEventHandler handler) {
        for (int i = 0; i < handlers.length; i++) {
            if (handlers[i] == handler) {
                AsyncEventHandler[] h = new AsyncEventHandler[handlers.length - 1];
                System.arraycopy(handlers, 0, h, 0, i);
                System.arraycopy(handlers, i + 1, h, i, handlers.length - i - 1);
                handlers = h;
                return;
            }
        }
    }

    /** Makes {@code handler} the only handler (null: none). */
    public synchronized void setHandler(AsyncEventHandler handler) {
        handlers = new AsyncEventHandler[0];
        if (handler != null) {
            addHandler(handler);
        }
    }

    /** Whether {@code handler} is attached. */
    public synchronized boolean handledBy(AsyncEventHandler handler) {
        for (AsyncEventHandler h : handlers) {
            if (h == handler) {
                return true;
            }
        }
        return false;
    }

    /** Releases every attached handler once. */
    public void fire() {
        AsyncEventHandler[] h;
        synchronized (this) {
            h = handlers;
        }
        for (int i = 0; i < h.length; i++) {
            h[i].fired();
        }
    }
}
