package org.jmclbench.core.policy;

/**
 * What happens to an event released while a job works on the robot (SPEC section 4): the one
 * definition of the policies, shared by every Java module (the Java SE engine's gates, the SCJ
 * mission's {@code JobGate}, the HVM run file, the matrix, verification). The C baseline keeps
 * the same codes in {@code native/src/policy.h}.
 *
 * <p>Job code looks a policy up with {@link #ofCode(long)} or {@link #ofLabel(String)}, never
 * {@code values()}, which allocates a copy of the constants on every call.
 */
public enum OverrunPolicy {
    /** The new event is dropped (the thesis's SkipTest). */
    SKIP(0, "skip", "SkipTest"),
    /** The job in progress is asked to abort, polled every poll interval, and the new event runs (TermTest). */
    TERMINATE(1, "terminate", "TermTest"),
    /** Every event is processed in release order; one completed after its deadline is late (QueueTest). */
    QUEUE(2, "queue", "QueueTest");

    /** The stable code of files and protocols (the HVM run file, the C baseline's {@code jm_policy}). */
    public final int code;
    /** The option value ({@code --policy}) and summary.json name. */
    public final String label;
    /** The thesis's test name: the run path's folder and the label of its charts. */
    public final String folder;

    OverrunPolicy(int code, String label, String folder) {
        this.code = code;
        this.label = label;
        this.folder = folder;
    }

    /** The policy of a code, or null when no policy has it. */
    public static OverrunPolicy ofCode(long code) {
        if (code == SKIP.code) {
            return SKIP;
        }
        if (code == TERMINATE.code) {
            return TERMINATE;
        }
        if (code == QUEUE.code) {
            return QUEUE;
        }
        return null;
    }

    /** The policy of an option value ({@code skip}, {@code terminate}, {@code queue}), or null. */
    public static OverrunPolicy ofLabel(String label) {
        if (SKIP.label.equals(label)) {
            return SKIP;
        }
        if (TERMINATE.label.equals(label)) {
            return TERMINATE;
        }
        if (QUEUE.label.equals(label)) {
            return QUEUE;
        }
        return null;
    }
}
