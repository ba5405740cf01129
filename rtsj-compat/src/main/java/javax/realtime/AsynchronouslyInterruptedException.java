package javax.realtime;

import org.jmclbench.rtsjcompat.AtcState;

/**
 * Asynchronous transfer of control (RTSJ 1.0.2 chapter 8, kept by RTSJ 2.0).
 *
 * <p>{@link #fire()} makes this AIE pending on the schedulable that runs its
 * {@link #doInterruptible(Interruptible)}; it is thrown there at the next delivery point of
 * AI-enabled code (a method declaring {@code throws AsynchronouslyInterruptedException}), never
 * in synchronized code, a non-AI method or a {@code finally}: on this layer the delivery points
 * are calls to {@link org.jmclbench.rtsjcompat.Atc#poll()} that the build weaves into AI-enabled
 * methods. Catching the AIE does not clear it: it is thrown again at the next delivery point
 * until {@link #clear()} or {@link #happened(boolean)} is called or its doInterruptible ends.
 * The exception object is thrown as it is, without a stack trace, so a delivery allocates nothing.
 */
public class AsynchronouslyInterruptedException extends InterruptedException {
    private static final long serialVersionUID = 1L;
    private static final AsynchronouslyInterruptedException GENERIC = new AsynchronouslyInterruptedException();

    // The state of the thread running this AIE's doInterruptible (null: none in progress), and
    // the depth of that call there; written under this object's monitor.
    private AtcState target;
    private int depth;
    private volatile boolean enabled = true;

    /** A new AIE, enabled, with no doInterruptible in progress. */
    public AsynchronouslyInterruptedException() {
        super();
    }

    /** No stack trace: the AIE is preallocated and thrown many times, allocation-free. */
    @Override
    public synchronized Throwable fillInStackTrace() {
        return this;
    }

    /**
     * The generic AIE, which {@link RealtimeThread#interrupt()} makes pending; the innermost
     * doInterruptible it unwinds clears it.
     */
    public static AsynchronouslyInterruptedException getGeneric() {
        return GENERIC;
    }

    /**
     * Makes this AIE pending on the schedulable running its doInterruptible. True when that
     * call is in progress, this AIE is enabled and is now pending there; false otherwise (no
     * doInterruptible in progress, disabled, or an AIE of an enclosing doInterruptible already
     * pending). A disabled AIE is made pending all the same and delivered once enabled.
     */
    public boolean fire() {
        AtcState s;
        int d;
        synchronized (this) {
            s = target;
            d = depth;
        }
        if (s == null) {
            return false;
        }
        boolean pending = s.makePending(this, d);
        synchronized (this) {
            if (target != s) {
                // its doInterruptible ended meanwhile and cleared it, or will: nothing to deliver
                s.clear(this);
                return false;
            }
        }
        return pending && enabled;
    }

    /**
     * Runs {@code logic.run(this)} on the calling schedulable, interruptible by {@link #fire()}.
     * When run is interrupted by this AIE (or the generic one), the AIE is cleared and
     * {@code logic.interruptAction(this)} runs; the AIE never escapes this call. An AIE of an
     * enclosing doInterruptible stays pending and is delivered in the caller. Returns false at
     * once when this AIE's doInterruptible is already in progress (in any schedulable), true
     * when logic ran (completed or interrupted).
     */
    public boolean doInterruptible(Interruptible logic) {
        if (logic == null) {
            throw new IllegalArgumentException("logic is null");
        }
        AtcState s = AtcState.current();
        if (s == null) {
            throw new IllegalThreadStateException("doInterruptible needs a schedulable (a RealtimeThread or an event handler)");
        }
        synchronized (this) {
            if (target != null) {
                return false;
            }
            depth = s.enter();
            target = s;
        }
        boolean interrupted = false;
        boolean mine;
        try {
            logic.run(this);
        } catch (AsynchronouslyInterruptedException e) {
            interrupted = true;
        } finally {
            synchronized (this) {
                target = null;
            }
            s.exit();
            // Whatever this call was asked to handle is cleared, however the logic ended (another
            // throwable included: found by the rtsj engine's JPF check); an outer AIE stays for the caller.
            mine = s.clear(this) | s.clear(GENERIC);
        }
        AsynchronouslyInterruptedException p = s.pending();
        if (interrupted && (mine || p == null)) {
            logic.interruptAction(this);
        }
        return true;
    }

    /** Clears this AIE if it is pending on the calling schedulable; true when it was. */
    public boolean clear() {
        AtcState s = AtcState.current();
        return s != null && s.clear(this);
    }

    /**
     * For a catch clause: true (and this AIE cleared) when this AIE is the one pending on the
     * calling schedulable. Otherwise false; another pending AIE stays pending and, whatever
     * {@code propagate} says, is thrown again at the caller's next delivery point.
     */
    public boolean happened(boolean propagate) {
        return clear();
    }

    /**
     * Enables delivery of this AIE. Valid only in its own doInterruptible: true when it was
     * disabled and the call is made there, false (and nothing done) otherwise. A pending AIE is
     * delivered at the next delivery point.
     */
    public boolean enable() {
        return setEnabled(true);
    }

    /** Defers delivery of this AIE (it can still be made pending); the rules of {@link #enable()}. */
    public boolean disable() {
        return setEnabled(false);
    }

    /** Whether delivery is enabled. */
    public boolean isEnabled() {
        return enabled;
    }

    private boolean setEnabled(boolean value) {
        AtcState s = AtcState.current();
        synchronized (this) {
            if (s == null || target != s || enabled == value) {
                return false;
            }
            enabled = value;
        }
        s.enabledChanged(this);
        return true;
    }

    /** Makes the generic AIE pending on {@code s} if a doInterruptible is in progress there. */
    static boolean interruptGeneric(AtcState s) {
        return s.depth() > 0 && s.makePending(GENERIC, -1);
    }
}
