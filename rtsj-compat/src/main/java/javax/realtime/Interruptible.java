package javax.realtime;

/**
 * Code run by {@link AsynchronouslyInterruptedException#doInterruptible(Interruptible)}: its
 * {@link #run} is interruptible only if the implementation declares
 * {@code throws AsynchronouslyInterruptedException}.
 */
public interface Interruptible {
    /** The interruptible work; {@code exception} is the AIE whose doInterruptible calls it. */
    void run(AsynchronouslyInterruptedException exception) throws AsynchronouslyInterruptedException;

    /** Called by doInterruptible after {@link #run} was interrupted by {@code exception}. */
    void interruptAction(AsynchronouslyInterruptedException exception);
}
