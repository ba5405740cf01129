package org.jmclbench.verification.jpf;

import gov.nasa.jpf.Config;
import gov.nasa.jpf.JPF;
import gov.nasa.jpf.search.Search;
import gov.nasa.jpf.vm.ThreadInfo;
import gov.nasa.jpf.vm.VM;
import org.jmclbench.verification.Property;

import java.util.ArrayList;
import java.util.List;

/**
 * P1 for a program whose main thread waits with a timeout: the rtsj engine joins its dispatcher
 * for a bounded time so that a hang is a recorded failure, and JPF's own deadlock property never
 * fires while a thread can still time out. This one is JPF's property with the timed waiters
 * counted as blocked: a state where threads are alive but every one is blocked on a lock or waits
 * (timed or not), and at least one waits without a timeout, is a deadlock (a lock cycle, a lock
 * never released, a lost notification). With {@code jmclbench.timeout.last} a timed waiter runs
 * only in such a state, so none is missed. Located at each stuck thread's innermost program
 * frame (not the JDK's, JPF's, nor the RTSJ layer's).
 */
public final class TimedDeadlockListener extends RuleListener {
    public TimedDeadlockListener(Config config, JPF jpf) {
    }

    @Override
    public Property property() {
        return Property.P1;
    }

    @Override
    public boolean check(Search search, VM vm) {
        if (violation == null) {
            List<String> at = stuck(vm);
            if (at != null) {
                violation = "deadlock: every thread is blocked or waits, and only a timeout could end it; stuck at " + at;
                where.addAll(at);
            }
        }
        return violation == null;
    }

    /** The stuck threads' program frames, or null when a thread can run or none waits without a timeout. */
    private static List<String> stuck(VM vm) {
        List<String> at = new ArrayList<>();
        boolean untimed = false;
        for (ThreadInfo ti : vm.getThreadList().getThreads()) {
            if (!ti.isAlive()) {
                continue;
            }
            if (ti.isTimeoutWaiting()) {
                continue;
            }
            if (!ti.isBlocked() && !ti.isWaiting()) {
                return null; // runnable (or about to be)
            }
            untimed = true;
            for (String f : RuleListener.frames(ti, null)) {
                if (!f.startsWith("javax.") && !f.startsWith("org.jmclbench.rtsjcompat.")) {
                    at.add(f);
                    break;
                }
            }
        }
        return untimed ? at : null;
    }
}
