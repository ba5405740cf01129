package javax.realtime;

/** Marks a handler bound to its own thread of control. */
public interface BoundAbstractAsyncEventHandler {
}
