package org.jmclbench.verification.jpf;

import gov.nasa.jpf.Config;
import gov.nasa.jpf.JPF;
import gov.nasa.jpf.vm.ClassInfo;
import gov.nasa.jpf.vm.ElementInfo;
import gov.nasa.jpf.vm.MethodInfo;
import gov.nasa.jpf.vm.StackFrame;
import gov.nasa.jpf.vm.ThreadInfo;
import gov.nasa.jpf.vm.VM;
import org.jmclbench.verification.Property;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

/**
 * P9, RTSJ's rules for asynchronous transfer of control as the rtsj engine relies on them:
 * <ul>
 * <li>an AIE is delivered (thrown by rtsj-compat's {@code Atc.poll}) only at a delivery point
 * of an AI-enabled method (the caller of {@code Atc.poll} declares the AIE) and never while the
 * thread holds a monitor (synchronized code, however deep);
 * <li>it is delivered in the {@code doInterruptible} call it was fired at: each call gets a token
 * (a frame attribute), a successful {@code fire()} copies the token of its target's call to the
 * AIE (an object attribute), and a delivery must find the same token on the innermost
 * doInterruptible of that AIE on the stack (an AIE left pending by a call that ended, and
 * delivered in the next one, has the old token);
 * <li>an AIE never escapes its doInterruptible: when an AIE is thrown, no doInterruptible frame
 * lies between the thrower and the frame that will handle it.
 * </ul>
 * Both attributes are JPF state, so they backtrack with the search. Located at the offending
 * frames (the doInterruptible, the method holding the monitor, the non-AI caller).
 */
public final class AtcListener extends RuleListener {
    static final String AIE = "javax.realtime.AsynchronouslyInterruptedException";
    private static final String DO_INTERRUPTIBLE = "doInterruptible";
    private static final String ATC = "org.jmclbench.rtsjcompat.Atc";
    private static final String DELIVERY_POINT = "poll";
    private int serial;

    /** The token of one doInterruptible call (a frame attribute) and of the call an AIE was fired at (an object attribute). */
    record Token(int serial) {
    }

    public AtcListener(Config config, JPF jpf) {
    }

    @Override
    public Property property() {
        return Property.P9;
    }

    @Override
    public void methodEntered(VM vm, ThreadInfo ti, MethodInfo mi) {
        if (isDoInterruptible(mi)) {
            ti.getModifiableTopFrame().setFrameAttr(new Token(++serial));
        }
    }

    @Override
    public void methodExited(VM vm, ThreadInfo ti, MethodInfo mi) {
        if (!mi.getName().equals("fire") || !mi.getClassInfo().isInstanceOf(AIE) || ti.getPendingException() != null) {
            return;
        }
        int aie = ti.getTopFrame().getThis();
        ElementInfo e = vm.getHeap().get(aie);
        ElementInfo state = vm.getHeap().get(e.getReferenceField("target"));
        if (state == null || state.getReferenceField("pending") != aie) {
            return; // not made pending: nothing will be delivered
        }
        ThreadInfo target = vm.getThreadList().getThreadInfoForObjRef(state.getReferenceField("owner"));
        StackFrame call = target == null ? null : callOf(target, aie);
        if (call != null) {
            HeldLockListener.replaceAttr(vm.getHeap().getModifiable(aie), Token.class, call.getFrameAttr());
        }
    }

    @Override
    public void exceptionThrown(VM vm, ThreadInfo ti, ElementInfo thrown) {
        if (violation != null || !thrown.getClassInfo().isInstanceOf(AIE)) {
            return;
        }
        int aie = thrown.getObjectRef();
        StackFrame top = ti.getTopFrame();
        if (top.getMethodInfo().getClassName().equals(ATC) && top.getMethodInfo().getName().equals(DELIVERY_POINT)) {
            checkDelivery(vm, ti, thrown, aie);
        }
        if (violation == null) {
            checkEscape(ti, thrown.getClassInfo());
        }
    }

    private void checkDelivery(VM vm, ThreadInfo ti, ElementInfo thrown, int aie) {
        StackFrame point = ti.getTopFrame().getPrevious(); // the caller of Atc.poll
        MethodInfo at = point == null ? null : point.getMethodInfo();
        if (at == null || !Arrays.asList(at.getThrownExceptionClassNames() == null ? new String[0]
                : at.getThrownExceptionClassNames()).contains(AIE)) {
            violated(ti, "an AIE was delivered in a method that is not AI-enabled: " + LocatedProperty.of(at),
                    List.of(LocatedProperty.of(at)));
            return;
        }
        List<ElementInfo> held = ti.getLockedObjects();
        StackFrame call = callOf(ti, aie);
        if (!held.isEmpty()) {
            List<String> sites = new ArrayList<>();
            for (ElementInfo m : held) {
                HeldLockListener.Site s = m.getObjectAttr(HeldLockListener.Site.class);
                sites.add(s == null ? "?" : s.where());
            }
            sites.addAll(RuleListener.frames(ti, call));
            violated(ti, "an AIE was delivered inside synchronized code (holding " + held.size() + " monitor(s), taken at "
                    + sites + ")", sites);
            return;
        }
        Token fired = vm.getHeap().get(aie).getObjectAttr(Token.class);
        if (call == null || fired == null || !fired.equals(call.getFrameAttr())) {
            List<String> l = new ArrayList<>();
            if (call != null) {
                l.add(LocatedProperty.of(call.getMethodInfo()));
                if (call.getPrevious() != null) {
                    l.addAll(RuleListener.frames(ti, call.getPrevious()));
                }
            }
            violated(ti, "an AIE was delivered in a doInterruptible it was not fired at" + (fired == null
                    ? " (never fired)" : " (fired at an earlier call, left pending)"), l);
        }
    }

    private void checkEscape(ThreadInfo ti, ClassInfo type) {
        for (StackFrame f = ti.getTopFrame(); f != null; f = f.getPrevious()) {
            if (f.getMethodInfo() != null && f.getMethodInfo().getHandlerFor(type, f.getPC()) != null) {
                return; // handled here, before any doInterruptible is left
            }
            if (f.getMethodInfo() != null && isDoInterruptible(f.getMethodInfo())) {
                violated(ti, "an AIE escaped its doInterruptible", List.of(LocatedProperty.of(f.getMethodInfo())));
                return;
            }
        }
        if (ti.getTopFrame() != null) {
            violated(ti, "an AIE was thrown outside any doInterruptible and not handled",
                    List.of(LocatedProperty.of(ti.getTopFrame().getMethodInfo())));
        }
    }

    /** The innermost doInterruptible frame of {@code aie} on {@code ti}'s stack, or null. */
    private static StackFrame callOf(ThreadInfo ti, int aie) {
        for (StackFrame f = ti.getTopFrame(); f != null; f = f.getPrevious()) {
            if (f.getMethodInfo() != null && isDoInterruptible(f.getMethodInfo()) && f.getThis() == aie) {
                return f;
            }
        }
        return null;
    }

    private static boolean isDoInterruptible(MethodInfo mi) {
        return mi.getName().equals(DO_INTERRUPTIBLE) && mi.getClassName().equals(AIE);
    }
}
