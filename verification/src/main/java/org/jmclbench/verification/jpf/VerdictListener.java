package org.jmclbench.verification.jpf;

import gov.nasa.jpf.Config;
import gov.nasa.jpf.Error;
import gov.nasa.jpf.JPF;
import gov.nasa.jpf.ListenerAdapter;
import gov.nasa.jpf.report.Statistics;
import gov.nasa.jpf.search.Search;
import gov.nasa.jpf.vm.ElementInfo;
import gov.nasa.jpf.vm.ExceptionInfo;
import gov.nasa.jpf.vm.Heap;
import gov.nasa.jpf.vm.MJIEnv;
import gov.nasa.jpf.vm.MethodInfo;
import gov.nasa.jpf.vm.NoUncaughtExceptionsProperty;
import gov.nasa.jpf.vm.NotDeadlockedProperty;
import gov.nasa.jpf.vm.StackFrame;
import gov.nasa.jpf.vm.ThreadInfo;
import gov.nasa.jpf.vm.VM;
import org.jmclbench.verification.Property;
import org.jmclbench.verification.mission.PropertyFailure;

import java.io.IOException;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.nio.file.StandardCopyOption;
import java.util.ArrayList;
import java.util.List;
import java.util.Properties;

/**
 * Writes a JPF run's outcome (errors, search constraints, statistics) as a properties file
 * named by {@code jmclbench.verdict}, so the host reads a structured verdict rather than
 * parsing JPF's console report. Each error is classified when it happens, while the VM is in
 * the violating state: which {@link Property} it violates and where ({@code Class.method}).
 * Our listeners say so themselves ({@link LocatedProperty}); a deadlock is P1 at each blocked
 * thread's place in the program; an uncaught {@link PropertyFailure} (or one that is the cause
 * of the uncaught exception) is its property at its culprit's method.
 */
public final class VerdictListener extends ListenerAdapter {
    /** Class-name prefixes of code that is not the program's: a blocked thread is located outside it. */
    private static final String[] NOT_PROGRAM = {"java.", "jdk.", "sun.", "gov.nasa."};

    private final Path out;
    private String constraint;
    private final List<String> violated = new ArrayList<>();
    private final List<List<String>> locations = new ArrayList<>();
    // Outcomes reached on any path (Coverage.reached), not backtracked: the search's union.
    private final java.util.SortedSet<String> reached = new java.util.TreeSet<>();

    public VerdictListener(Config config, JPF jpf) {
        String file = config.getString("jmclbench.verdict");
        if (file == null) {
            throw new IllegalArgumentException("VerdictListener needs +jmclbench.verdict=FILE");
        }
        this.out = Paths.get(file);
    }

    @Override
    public void searchConstraintHit(Search search) {
        // A depth or memory limit means the search did not cover the whole state space.
        constraint = search.getLastSearchConstraint();
    }

    @Override
    public void methodEntered(VM vm, ThreadInfo ti, MethodInfo mi) {
        if (mi.getName().equals(Coverage.METHOD) && mi.getClassName().equals(Coverage.class.getName())) {
            int ref = ti.getTopFrame().getLocalVariable(0);
            if (ref != MJIEnv.NULL) {
                reached.add(vm.getHeap().get(ref).asString());
            }
        }
    }

    @Override
    public void propertyViolated(Search search) {
        gov.nasa.jpf.Property p = search.getCurrentError().getProperty();
        VM vm = search.getVM();
        List<String> at = new ArrayList<>();
        String property = null;
        if (p instanceof LocatedProperty lp) {
            property = lp.property().name();
            at.addAll(lp.locations());
        } else if (p instanceof NotDeadlockedProperty) {
            property = Property.P1.name();
            for (ThreadInfo ti : vm.getLiveThreads()) {
                if (!ti.isTerminated()) {
                    at.add(programFrame(ti));
                }
            }
        } else if (p instanceof NoUncaughtExceptionsProperty u && u.getUncaughtExceptionInfo() != null) {
            ExceptionInfo x = u.getUncaughtExceptionInfo();
            ElementInfo failure = failureIn(vm.getHeap(), x.getException());
            if (failure != null) {
                ElementInfo prop = vm.getHeap().get(failure.getReferenceField(PropertyFailure.PROPERTY_FIELD));
                property = prop.getStringField("name");
                ElementInfo culprit = vm.getHeap().get(failure.getReferenceField(PropertyFailure.CULPRIT_FIELD));
                at.add((culprit == null ? "?" : culprit.getClassInfo().getName()) + "."
                        + failure.getStringField(PropertyFailure.METHOD_FIELD));
            } else {
                at.add(x.getExceptionClassname() + " in " + programFrame(x.getThread()));
            }
        }
        violated.add(property == null ? "" : property);
        locations.add(at);
    }

    /** The PropertyFailure among an exception and its causes, or null. */
    private static ElementInfo failureIn(Heap heap, ElementInfo x) {
        for (int depth = 0; x != null && depth < 8; depth++) {
            if (x.getClassInfo().isInstanceOf(PropertyFailure.class.getName())) {
                return x;
            }
            int cause = x.getReferenceField("cause");
            x = cause == MJIEnv.NULL || cause == x.getObjectRef() ? null : heap.get(cause);
        }
        return null;
    }

    /** The topmost frame of a thread that is the program's own code, as {@code Class.method}. */
    private static String programFrame(ThreadInfo ti) {
        for (StackFrame f = ti == null ? null : ti.getTopFrame(); f != null; f = f.getPrevious()) {
            MethodInfo mi = f.getMethodInfo();
            if (mi != null && !startsWithAny(mi.getClassName(), NOT_PROGRAM)) {
                return LocatedProperty.of(mi);
            }
        }
        return "?";
    }

    private static boolean startsWithAny(String s, String[] prefixes) {
        for (String p : prefixes) {
            if (s.startsWith(p)) {
                return true;
            }
        }
        return false;
    }

    @Override
    public void searchFinished(Search search) {
        Properties p = new Properties();
        List<Error> errors = search.getErrors();
        p.setProperty("errors", Integer.toString(errors.size()));
        for (int i = 0; i < errors.size(); i++) {
            Error e = errors.get(i);
            p.setProperty("error." + i + ".property", e.getProperty().getClass().getSimpleName());
            // The details are what the property said when it was violated (the uncaught
            // exception with its stack, the deadlocked threads, the racing accesses).
            String d = e.getDetails();
            d = d == null ? "" : d.replaceAll("\\s+", " ").trim();
            p.setProperty("error." + i + ".message", d.length() > 4000 ? d.substring(0, 4000) : d);
            if (i < violated.size()) {
                p.setProperty("error." + i + ".violates", violated.get(i));
                p.setProperty("error." + i + ".locations", String.join(",", locations.get(i)));
            }
        }
        p.setProperty("reached", String.join(",", reached));
        if (constraint != null) {
            p.setProperty("constraint", constraint);
        }
        Statistics s = search.getVM().getJPF().getReporter().getStatistics();
        p.setProperty("states.new", Long.toString(s.newStates));
        p.setProperty("states.visited", Long.toString(s.visitedStates));
        p.setProperty("states.end", Long.toString(s.endStates));
        p.setProperty("maxDepth", Integer.toString(s.maxDepth));
        p.setProperty("instructions", Long.toString(s.insns));
        p.setProperty("done", "true");
        // written whole or not at all: a JVM killed at the budget mid-write left a verdict without its errors
        Path partial = out.resolveSibling(out.getFileName() + ".partial");
        try {
            try (Writer w = Files.newBufferedWriter(partial, StandardCharsets.UTF_8)) {
                p.store(w, "jmclbench JPF verdict");
            }
            Files.move(partial, out, StandardCopyOption.ATOMIC_MOVE, StandardCopyOption.REPLACE_EXISTING);
        } catch (IOException e) {
            throw new IllegalStateException("cannot write " + out, e);
        }
    }
}
