package org.jmclbench.verification.jpf;

import java.util.List;

import gov.nasa.jpf.Config;
import gov.nasa.jpf.JPF;
import gov.nasa.jpf.jvm.bytecode.AASTORE;
import gov.nasa.jpf.jvm.bytecode.LDC;
import gov.nasa.jpf.jvm.bytecode.PUTFIELD;
import gov.nasa.jpf.jvm.bytecode.PUTSTATIC;
import gov.nasa.jpf.vm.ElementInfo;
import gov.nasa.jpf.vm.FieldInfo;
import gov.nasa.jpf.vm.Instruction;
import gov.nasa.jpf.vm.MJIEnv;
import gov.nasa.jpf.vm.MethodInfo;
import gov.nasa.jpf.vm.StackFrame;
import gov.nasa.jpf.vm.ThreadInfo;
import gov.nasa.jpf.vm.VM;
import gov.nasa.jpf.vm.bytecode.FieldInstruction;
import org.jmclbench.rtsjcompat.Area;
import org.jmclbench.rtsjcompat.ScjThread;


/**
 * P6, the SCJ reference rule: no object stores a reference to an object of a shorter-lived
 * area. Each new object is tagged with its area, the allocating thread's current allocation
 * context (rtsj-compat's {@code ScjThread.current}, an {@code Area} whose {@code parent} chain
 * is the lifetime order); on every reference store ({@code putfield}, {@code aastore},
 * {@code putstatic}: a static field lives in immortal memory) the value's area must be the
 * holder's area or one of its ancestors ({@code Area.mayHoldReferenceTo}).
 *
 * <p>Untagged, so unchecked: objects created outside SCJ code (the driver's, a handler's between
 * releases), in class initialisation (immortal on an SCJ VM), {@code ldc} strings and Class
 * objects. Stores executed by the SCJ infrastructure itself are not checked (on an SCJ VM it is
 * the VM): {@code jmclbench.areas.exempt}, class-name prefixes (default the JDK, JPF and
 * rtsj-compat's internals). {@code jmclbench.areas.known}: fields ({@code Class.field}) whose
 * violations are known findings, reported elsewhere and not flagged again. The tag is a JPF
 * object attribute, so it backtracks with the heap.
 */
public final class AreaReferenceListener extends MemoryRuleListener {

    /** The area an object was allocated in (the heap reference of its {@code Area}), and by which method. */
    static final class AreaTag {
        final int area;
        final MethodInfo allocator;

        AreaTag(int area, MethodInfo allocator) {
            this.area = area;
            this.allocator = allocator;
        }
    }

    private final String[] exempt;
    private final String[] known;
    private final boolean emptied;

    public AreaReferenceListener(Config config, JPF jpf) {
        this.exempt = config.getStringArray("jmclbench.areas.exempt",
                new String[] {"java.", "javax.", "jdk.", "sun.", "gov.nasa.", "org.jmclbench.rtsjcompat."});
        this.known = config.getStringArray("jmclbench.areas.known", new String[0]);
        this.emptied = config.getBoolean("jmclbench.areas.emptied", true);
    }

    @Override
    public void objectCreated(VM vm, ThreadInfo ti, ElementInfo ei) {
        if (ti == null || ti.getPC() instanceof LDC || ei.getClassInfo().getName().equals("java.lang.Class")) {
            return;
        }
        ElementInfo thread = ti.getThreadObject();
        if (thread == null || !thread.getClassInfo().isInstanceOf(ScjThread.class.getName())) {
            return;
        }
        int area = thread.getReferenceField(ScjThread.CURRENT_FIELD);
        if (area == MJIEnv.NULL) {
            return;
        }
        MethodInfo allocator = null;
        for (StackFrame f = ti.getTopFrame(); f != null; f = f.getPrevious()) {
            MethodInfo mi = f.getMethodInfo();
            if (mi != null && mi.isClinit()) {
                return;
            }
            if (allocator == null && mi != null && !exempt(mi)) {
                allocator = mi;
            }
        }
        ei.addObjectAttr(new AreaTag(area, allocator));
    }

    /**
     * The private memory is empty after each release: when rtsj-compat empties a private area
     * ({@code Area.empty()}), no object allocated in it may still be reachable. A store the
     * reference rule cannot see (one made by exempt code: the JDK's, a native array copy) shows
     * here. The collector runs first, so only reachable objects remain. A release that failed
     * is left alone: its exception, made in the area, is rightly on its way out.
     */
    @Override
    public void methodEntered(VM vm, ThreadInfo ti, MethodInfo mi) {
        if (violation != null || !emptied || !mi.getName().equals("empty")
                || !mi.getClassName().equals(Area.class.getName())) {
            return;
        }
        ElementInfo area = vm.getHeap().get(ti.getTopFrame().getThis());
        if (area.getIntField(Area.KIND_FIELD) < Area.PRIVATE || failing(vm, ti)) {
            return;
        }
        vm.getKernelState().gc();
        for (ElementInfo ei : vm.getHeap().liveObjects()) {
            AreaTag t = ei.getObjectAttr(AreaTag.class);
            if (t != null && t.area == area.getObjectRef()) {
                String location = LocatedProperty.of(t.allocator);
                violated(ti, "an object of " + ei.getClassInfo().getName() + " allocated by " + location + " in "
                        + name(vm, t.area) + " is still reachable when the release ends", List.of(location));
                return;
            }
        }
    }

    /** Whether a frame of the thread holds a Throwable (the release is failing). */
    private static boolean failing(VM vm, ThreadInfo ti) {
        for (StackFrame f = ti.getTopFrame(); f != null; f = f.getPrevious()) {
            for (int i = 0; i < f.getLocalVariableCount(); i++) {
                if (f.isLocalVariableRef(i)) {
                    ElementInfo v = vm.getHeap().get(f.getLocalVariable(i));
                    if (v != null && v.getClassInfo().isInstanceOf("java.lang.Throwable")) {
                        return true;
                    }
                }
            }
        }
        return false;
    }

    @Override
    public void executeInstruction(VM vm, ThreadInfo ti, Instruction insn) {
        if (violation != null) {
            return;
        }
        int holder;
        int value;
        boolean isStatic = false;
        StackFrame frame = ti.getTopFrame();
        if (insn instanceof PUTFIELD) {
            if (!storesReference((PUTFIELD) insn)) {
                return;
            }
            value = frame.peek(0);
            holder = frame.peek(1);
        } else if (insn instanceof AASTORE) {
            value = frame.peek(0);
            holder = frame.peek(2);
        } else if (insn instanceof PUTSTATIC) {
            if (!storesReference((PUTSTATIC) insn)) {
                return;
            }
            value = frame.peek(0);
            holder = MJIEnv.NULL;
            isStatic = true;
        } else {
            return;
        }
        if (value == MJIEnv.NULL || (!isStatic && holder == MJIEnv.NULL) || exempt(insn.getMethodInfo())) {
            return;
        }
        int valueArea = areaOf(vm, value);
        if (valueArea == MJIEnv.NULL) {
            return;
        }
        int holderArea = isStatic ? MJIEnv.NULL : areaOf(vm, holder);
        if (!isStatic && holderArea == MJIEnv.NULL) {
            return;
        }
        if (isStatic ? depth(vm, valueArea) == 0 : mayHold(vm, holderArea, valueArea)) {
            return;
        }
        String field = insn instanceof PUTFIELD ? ((PUTFIELD) insn).getFieldInfo().getFullName()
                : insn instanceof PUTSTATIC ? ((PUTSTATIC) insn).getFieldInfo().getFullName() : null;
        for (String k : known) {
            if (k.equals(field)) {
                return;
            }
        }
        String target = isStatic ? "static field " + field
                : (field == null ? "an array " : "field " + field + " of an object ") + "in " + name(vm, holderArea);
        String location = LocatedProperty.of(insn.getMethodInfo());
        violated(ti, location + ":" + insn.getLineNumber() + " stores a reference to an object of "
                + vm.getHeap().get(value).getClassInfo().getName() + " in " + name(vm, valueArea)
                + " (shorter-lived) into " + target, List.of(location));
    }

    /** Whether the field holds a reference; JPF's isReferenceField is false for primitive arrays. */
    private static boolean storesReference(FieldInstruction insn) {
        if (insn.isReferenceField()) {
            return true;
        }
        if (insn.getFieldSize() != 1) {
            return false;
        }
        try {
            FieldInfo fi = insn.getFieldInfo();
            return fi != null && fi.isReference();
        } catch (RuntimeException e) {
            return false; // class not loaded yet: JPF resolves it when the store executes
        }
    }

    private boolean exempt(MethodInfo mi) {
        if (mi == null) {
            return true;
        }
        String cls = mi == null ? "" : mi.getClassName();
        for (String p : exempt) {
            if (cls.startsWith(p)) {
                return true;
            }
        }
        return false;
    }

    private static int areaOf(VM vm, int ref) {
        ElementInfo ei = vm.getHeap().get(ref);
        AreaTag t = ei == null ? null : ei.getObjectAttr(AreaTag.class);
        return t == null ? MJIEnv.NULL : t.area;
    }

    /** Whether {@code holder} is {@code value} or lives inside it (value is an ancestor). */
    private static boolean mayHold(VM vm, int holder, int value) {
        for (int a = holder; a != MJIEnv.NULL; a = vm.getHeap().get(a).getReferenceField(Area.PARENT_FIELD)) {
            if (a == value) {
                return true;
            }
        }
        return false;
    }

    private static int depth(VM vm, int area) {
        return vm.getHeap().get(area).getIntField(Area.DEPTH_FIELD);
    }

    private static String name(VM vm, int area) {
        ElementInfo a = vm.getHeap().get(area);
        return a.getStringField(Area.NAME_FIELD) + " (" + Area.kindName(a.getIntField(Area.KIND_FIELD)) + ")";
    }
}
