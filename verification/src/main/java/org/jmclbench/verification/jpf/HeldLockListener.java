package org.jmclbench.verification.jpf;

import gov.nasa.jpf.Config;
import gov.nasa.jpf.JPF;
import gov.nasa.jpf.vm.ElementInfo;
import gov.nasa.jpf.vm.MethodInfo;
import gov.nasa.jpf.vm.StackFrame;
import gov.nasa.jpf.vm.ThreadInfo;
import gov.nasa.jpf.vm.VM;
import org.jmclbench.verification.Property;

import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;

/**
 * P8: when a release of an RTSJ event handler ends ({@code AsyncEventHandler.handleAsyncEvent}
 * returns or is left by an exception), its thread holds no monitor and owns no
 * {@code ReentrantLock}: a job cut short by an AIE has released what it took. Each lock the
 * program takes is tagged with where (an object attribute, {@link Site}: the program method that
 * entered the monitor or called {@code lock()}), and a violation is located there.
 *
 * <p>Configuration: {@code jmclbench.lock.code}, class-name prefixes of the program whose lock
 * sites are recorded (default: the rtsj engine and the seeded bugs).
 */
public final class HeldLockListener extends RuleListener {
    private static final String RELEASE_CLASS = "javax.realtime.AsyncEventHandler";
    private static final String REENTRANT_LOCK = "java.util.concurrent.locks.ReentrantLock";
    private final String[] code;
    // ReentrantLocks seen taken (references; each is re-checked to be one before it is read).
    private final Set<Integer> locks = new LinkedHashSet<>();

    /** Where a lock was taken, as {@code Class.method}. */
    record Site(String where) {
    }

    public HeldLockListener(Config config, JPF jpf) {
        this.code = config.getStringArray("jmclbench.lock.code",
                new String[] {"org.jmclbench.workload.", "org.jmclbench.verification.seeded."});
    }

    @Override
    public Property property() {
        return Property.P8;
    }

    @Override
    public void objectLocked(VM vm, ThreadInfo ti, ElementInfo ei) {
        StackFrame f = ti.getTopFrame();
        MethodInfo mi = f == null ? null : f.getMethodInfo();
        if (mi != null && inCode(mi.getClassName())) {
            replaceAttr(vm.getHeap().getModifiable(ei.getObjectRef()), Site.class, new Site(LocatedProperty.of(mi)));
        }
    }

    @Override
    public void methodExited(VM vm, ThreadInfo ti, MethodInfo mi) {
        if (mi.getClassName().equals(REENTRANT_LOCK) && mi.getName().startsWith("lock")
                && ti.getPendingException() == null) {
            StackFrame caller = ti.getTopFrame().getPrevious();
            if (caller != null && caller.getMethodInfo() != null && inCode(caller.getMethodInfo().getClassName())) {
                int lock = ti.getTopFrame().getThis();
                locks.add(lock);
                replaceAttr(vm.getHeap().getModifiable(lock), Site.class, new Site(LocatedProperty.of(caller.getMethodInfo())));
            }
        } else if (mi.getName().equals("handleAsyncEvent") && mi.getClassName().equals(RELEASE_CLASS)) {
            releaseEnded(vm, ti);
        }
    }

    private void releaseEnded(VM vm, ThreadInfo ti) {
        List<String> sites = new ArrayList<>();
        for (ElementInfo m : ti.getLockedObjects()) {
            Site s = m.getObjectAttr(Site.class);
            sites.add(s == null ? m.getClassInfo().getName() + " monitor" : s.where());
        }
        for (int ref : locks) {
            ElementInfo lock = vm.getHeap().get(ref);
            if (lock == null || !lock.getClassInfo().isInstanceOf(REENTRANT_LOCK)) {
                continue;
            }
            ElementInfo sync = vm.getHeap().get(lock.getReferenceField("sync"));
            if (sync != null && sync.getReferenceField("exclusiveOwnerThread") == ti.getThreadObjectRef()) {
                Site s = lock.getObjectAttr(Site.class);
                sites.add(s == null ? "?" : s.where());
            }
        }
        if (!sites.isEmpty()) {
            violated(ti, "a release of " + ti.getName() + " ended holding " + sites.size() + " lock(s), taken at " + sites,
                    sites);
        }
    }

    private boolean inCode(String cls) {
        for (String p : code) {
            if (cls.startsWith(p)) {
                return true;
            }
        }
        return false;
    }

    /** Sets {@code ei}'s attribute of {@code type} to {@code value} (ei modifiable). */
    static void replaceAttr(ElementInfo ei, Class<?> type, Object value) {
        Object old = ei.getObjectAttr(type);
        if (old != null) {
            ei.removeObjectAttr(old);
        }
        if (value != null) {
            ei.addObjectAttr(value);
        }
    }
}
