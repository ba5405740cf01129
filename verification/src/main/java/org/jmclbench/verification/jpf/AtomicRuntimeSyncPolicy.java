package org.jmclbench.verification.jpf;

import gov.nasa.jpf.Config;
import gov.nasa.jpf.vm.AllRunnablesSyncPolicy;
import gov.nasa.jpf.vm.MethodInfo;
import gov.nasa.jpf.vm.StackFrame;
import gov.nasa.jpf.vm.ThreadInfo;

/**
 * JPF's scheduling policy with the SCJ layer taken as the virtual machine: a thread running
 * rtsj-compat's own code (a release, a wake-up, the virtual clock) is not preempted there, as
 * an SCJ VM's scheduler does these operations atomically. Every other point where JPF switches
 * threads stays: the mission's own monitors, field accesses JPF breaks on, and every point
 * where a thread blocks or ends (so no deadlock is hidden: a thread that blocks inside the
 * layer still hands over to every runnable thread).
 *
 * <p>What is given up: interleavings that preempt a thread inside the layer. They are the
 * layer's concern (tested by rtsj-compat's own tests), not the mission's; the mission's
 * interleavings (which job holds the robot, when a release falls within a job) all remain.
 *
 * <p>A frame belongs to the layer when the innermost frame that is not the JDK's is of a class
 * under {@code jmclbench.atomic.packages} (default: rtsj-compat's packages).
 *
 * <p>With {@code jmclbench.timeout.last=true}, a thread in a timed wait (a join or wait with a
 * timeout) times out only when no other thread can run: JPF has no clock, and would otherwise let
 * it time out at any scheduling point. A program whose timeout is a hang budget far beyond what it
 * does in virtual time (the rtsj engine joins its dispatcher for the replay's length plus two
 * minutes) then times out exactly when it is stuck, as it would on a real clock.
 */
public class AtomicRuntimeSyncPolicy extends AllRunnablesSyncPolicy {
    private static final String[] JDK = {"java.", "javax.management.", "jdk.", "sun.", "gov.nasa.jpf."};
    private final String[] atomic;
    private final boolean timeoutLast;

    public AtomicRuntimeSyncPolicy(Config config) {
        super(config);
        this.timeoutLast = config.getBoolean("jmclbench.timeout.last", false);
        this.atomic = config.getStringArray("jmclbench.atomic.packages",
                new String[] {"org.jmclbench.rtsjcompat.", "javax.realtime.", "javax.safetycritical."});
    }

    @Override
    protected boolean setNonBlockingCG(String id, ThreadInfo tiCurrent) {
        if (inLayer(tiCurrent)) {
            return false;
        }
        return super.setNonBlockingCG(id, tiCurrent);
    }

    @Override
    protected ThreadInfo[] getTimeoutRunnables(gov.nasa.jpf.vm.ApplicationContext appCtx) {
        ThreadInfo[] all = super.getTimeoutRunnables(appCtx);
        return timeoutLast ? timeoutLast(all) : all;
    }

    /** The threads of {@code all} that are not in a timed wait, or all of them when every one is. */
    static ThreadInfo[] timeoutLast(ThreadInfo[] all) {
        int running = 0;
        for (ThreadInfo t : all) {
            running += t.isTimeoutWaiting() ? 0 : 1;
        }
        if (running == 0 || running == all.length) {
            return all;
        }
        ThreadInfo[] r = new ThreadInfo[running];
        int i = 0;
        for (ThreadInfo t : all) {
            if (!t.isTimeoutWaiting()) {
                r[i++] = t;
            }
        }
        return r;
    }

    private boolean inLayer(ThreadInfo ti) {
        for (StackFrame f = ti.getTopFrame(); f != null; f = f.getPrevious()) {
            MethodInfo mi = f.getMethodInfo();
            if (mi == null || f.isDirectCallFrame()) {
                continue;
            }
            String cls = mi.getClassName();
            if (startsWithAny(cls, atomic)) {
                return true;
            }
            if (!startsWithAny(cls, JDK)) {
                return false;
            }
        }
        return false;
    }

    private static boolean startsWithAny(String name, String[] prefixes) {
        for (String p : prefixes) {
            if (name.startsWith(p)) {
                return true;
            }
        }
        return false;
    }
}
