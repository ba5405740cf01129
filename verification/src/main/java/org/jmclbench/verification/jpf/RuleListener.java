package org.jmclbench.verification.jpf;

import gov.nasa.jpf.PropertyListenerAdapter;
import gov.nasa.jpf.search.Search;
import gov.nasa.jpf.vm.MethodInfo;
import gov.nasa.jpf.vm.StackFrame;
import gov.nasa.jpf.vm.ThreadInfo;
import gov.nasa.jpf.vm.VM;

import java.util.ArrayList;
import java.util.List;

/**
 * A listener that checks one rule of ours as a JPF property: the first violation found on a
 * path, its message and its locations; the property fails once a violation is recorded, and the
 * transition is broken there, so the violating state is the one reported.
 */
abstract class RuleListener extends PropertyListenerAdapter implements LocatedProperty {
    /** The first violation's message, or null while the rule holds. */
    String violation;
    /** Where it happened, as {@code Class.method}. */
    final List<String> where = new ArrayList<>();

    /** Records a violation (the first one only) and ends the transition. */
    void violated(ThreadInfo ti, String message, List<String> locations) {
        if (violation != null) {
            return;
        }
        violation = message;
        where.clear();
        where.addAll(locations);
        ti.breakTransition("rule violated");
    }

    @Override
    public boolean check(Search search, VM vm) {
        return violation == null;
    }

    @Override
    public String getErrorMessage() {
        return violation;
    }

    @Override
    public List<String> locations() {
        return violation == null ? List.of() : List.copyOf(where);
    }

    @Override
    public void reset() {
        violation = null;
        where.clear();
    }

    /** {@code Class.method} of each frame from the top down to (not including) {@code stop}, the JDK's and JPF's left out. */
    static List<String> frames(ThreadInfo ti, StackFrame stop) {
        List<String> l = new ArrayList<>();
        for (StackFrame f = ti.getTopFrame(); f != null && f != stop; f = f.getPrevious()) {
            MethodInfo mi = f.getMethodInfo();
            if (mi != null && !f.isDirectCallFrame() && !mi.getClassName().startsWith("java.")
                    && !mi.getClassName().startsWith("jdk.") && !mi.getClassName().startsWith("gov.nasa.")) {
                l.add(LocatedProperty.of(mi));
            }
        }
        return l;
    }
}
