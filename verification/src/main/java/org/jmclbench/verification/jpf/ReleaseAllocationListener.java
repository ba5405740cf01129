package org.jmclbench.verification.jpf;

import java.util.List;

import gov.nasa.jpf.Config;
import gov.nasa.jpf.JPF;
import gov.nasa.jpf.jvm.bytecode.LDC;
import gov.nasa.jpf.vm.ElementInfo;
import gov.nasa.jpf.vm.MethodInfo;
import gov.nasa.jpf.vm.StackFrame;
import gov.nasa.jpf.vm.ThreadInfo;
import gov.nasa.jpf.vm.VM;


/**
 * P6, preallocated style: no object is created while a release runs, i.e. while a
 * {@code handleAsyncEvent} of a release class is on the allocating thread's stack. Class
 * initialisation ({@code <clinit>}) is exempt: it runs once per class, not per release, and an
 * SCJ VM does it before the mission starts. So is the String of an {@code ldc} constant: JPF
 * creates it when the instruction first runs, a JVM when it resolves the class's constants. And
 * so is the {@code java.lang.Class} object JPF creates when a class is first used (loading).
 *
 * <p>Configuration: {@code jmclbench.release.method} (default {@code handleAsyncEvent}) and
 * {@code jmclbench.release.classes}, class-name prefixes of the handlers whose releases must not
 * allocate (default: every class).
 */
public final class ReleaseAllocationListener extends MemoryRuleListener {
    private final String method;
    private final String[] classes;

    public ReleaseAllocationListener(Config config, JPF jpf) {
        this.method = config.getString("jmclbench.release.method", "handleAsyncEvent");
        this.classes = config.getStringArray("jmclbench.release.classes", new String[] {""});
    }

    @Override
    public void objectCreated(VM vm, ThreadInfo ti, ElementInfo ei) {
        if (violation != null || ti == null) {
            return;
        }
        if (ti.getPC() instanceof LDC || ei.getClassInfo().getName().equals("java.lang.Class")) {
            return;
        }
        String release = null;
        for (StackFrame f = ti.getTopFrame(); f != null; f = f.getPrevious()) {
            MethodInfo mi = f.getMethodInfo();
            if (mi == null) {
                continue;
            }
            if (mi.isClinit()) {
                return;
            }
            if (mi.getName().equals(method) && matches(mi.getClassName())) {
                release = mi.getClassName() + "." + method;
                break;
            }
        }
        if (release == null) {
            return;
        }
        StackFrame top = ti.getTopFrame();
        String location = top == null ? "?" : LocatedProperty.of(top.getMethodInfo());
        String at = top == null ? "?" : location + ":" + top.getLine();
        violated(ti, "release of " + release + " allocated a " + ei.getClassInfo().getName() + " at " + at, List.of(location));
    }

    private boolean matches(String cls) {
        for (String p : classes) {
            if (cls.startsWith(p)) {
                return true;
            }
        }
        return false;
    }
}
