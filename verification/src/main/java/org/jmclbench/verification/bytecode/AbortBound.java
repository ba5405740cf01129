package org.jmclbench.verification.bytecode;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.BitSet;
import java.util.Collection;
import java.util.Deque;
import java.util.HashMap;
import java.util.HashSet;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.function.Predicate;

import org.objectweb.asm.Opcodes;
import org.objectweb.asm.Type;
import org.objectweb.asm.tree.AbstractInsnNode;
import org.objectweb.asm.tree.ClassNode;
import org.objectweb.asm.tree.FieldInsnNode;
import org.objectweb.asm.tree.MethodInsnNode;
import org.objectweb.asm.tree.MethodNode;
import org.objectweb.asm.tree.TypeInsnNode;

/**
 * The static side of abort latency: over a terminable job's bytecode, the longest stretch, in
 * particle steps and bytecodes, between two points where an abort can take effect, and the
 * regions where it is deferred. Particle loops and their polls are {@link AbortPollCheck}'s
 * (one walk, one stride rule).
 *
 * <p>The points: under {@link Mode#COOPERATIVE} (Java SE, SCJ) every poll of the abort signal,
 * where the job sees the request and returns. Under {@link Mode#ATC} (RTSJ) a poll counts only
 * when the job's signal reaches a delivery point (a call of {@code Atc.poll}, woven into
 * AI-enabled methods); the signal is the one the entry hands the job (read from its reachable
 * {@code getstatic}s), and the synchronized blocks the job runs in are named as deferral regions.
 * A particle loop with no point in it runs whole after a request: its gap is unbounded, and when
 * no loop of the job has a point the bound is the whole job.
 */
public final class AbortBound {
    /** How an abort takes effect in the engine. */
    public enum Mode { COOPERATIVE, ATC }

    static final String SIGNAL = "org/jmclbench/core/mcl/AbortSignal";
    static final String DELIVERY_OWNER = "org/jmclbench/rtsjcompat/Atc";

    private final ClassPool pool;
    private final Predicate<String> follow;
    private final int interval;
    private final Mode mode;
    private final Map<String, String> known;

    /**
     * @param follow   the classes holding job code (internal names)
     * @param interval the poll interval, in particle steps
     * @param known    enum values fixed for the analysis (enum internal name to constant), e.g. a design
     */
    public AbortBound(ClassPool pool, Predicate<String> follow, int interval, Mode mode, Map<String, String> known) {
        this.pool = pool;
        this.follow = follow;
        this.interval = interval;
        this.mode = mode;
        this.known = known;
    }

    /** What the analysis found for the job reached from {@code entries}. */
    public record Result(List<AbortPollCheck.LoopGap> loops, Map<AbortPollCheck.LoopGap, Long> stepBytecodes,
                         List<String> signals, boolean signalDelivers, List<String> deferrals, int jobMethods) {
        /** The longest gap in particle steps; {@link Long#MAX_VALUE} when a loop runs whole (no point in it). */
        public long longestSteps() {
            return loops.stream().mapToLong(AbortPollCheck.LoopGap::steps).max().orElse(0);
        }

        /** True when no loop of the job has an abort point: after a request the whole job runs. */
        public boolean wholeJob() {
            return !loops.isEmpty() && loops.stream().allMatch(l -> l.steps() == AbortPollCheck.UNKNOWN);
        }

        /** The loop with the longest gap (of equal gaps, the one with the most bytecodes a step), or null without loops. */
        public AbortPollCheck.LoopGap longest() {
            AbortPollCheck.LoopGap best = null;
            for (AbortPollCheck.LoopGap l : loops) {
                if (best == null || l.steps() > best.steps()
                        || l.steps() == best.steps() && stepBytecodes.get(l) > stepBytecodes.get(best)) {
                    best = l;
                }
            }
            return best;
        }

        /** The most bytecodes between two points: the longest gap's steps times its step's bytecodes (MAX_VALUE: whole). */
        public long longestBytecodes() {
            AbortPollCheck.LoopGap l = longest();
            if (l == null) {
                return 0;
            }
            return l.steps() == AbortPollCheck.UNKNOWN ? Long.MAX_VALUE : l.steps() * stepBytecodes.get(l);
        }
    }

    /** Analyses the job reached from {@code entries}. */
    public Result analyse(Collection<ClassPool.Owned> entries) {
        List<String> signals = mode == Mode.ATC ? signals(entries) : List.of();
        boolean delivers = mode == Mode.COOPERATIVE || signals.stream().anyMatch(this::signalDelivers);
        Predicate<MethodInsnNode> poll = c -> c.name.equals("abortRequested") && c.desc.equals("()Z");
        List<AbortPollCheck.LoopGap> loops = new AbortPollCheck(pool, follow, interval)
                .polls(delivers ? poll : c -> false).known(known).gaps(entries);
        Map<AbortPollCheck.LoopGap, Long> bytecodes = new HashMap<>();
        for (AbortPollCheck.LoopGap l : loops) {
            bytecodes.put(l, stepBytecodes(l));
        }
        List<String> deferrals = new ArrayList<>();
        Set<ClassPool.Owned> reached = reached(entries);
        if (mode == Mode.ATC) {
            deferrals.addAll(monitorRegions(reached));
            if (!delivers) {
                deferrals.add("non-AI code: the job's " + reached.size() + " methods reach no delivery point (the job's signal "
                        + String.join(", ", signals.stream().map(s -> s.replace('/', '.')).toList())
                        + " calls none): the AIE stays pending until control is back in AI-enabled code after the job");
            }
        }
        for (AbortPollCheck.LoopGap l : loops) {
            if (l.steps() == AbortPollCheck.UNKNOWN && delivers) {
                deferrals.add(l.where() + ": particle loop with no abort point (runs whole after a request)");
            }
        }
        return new Result(loops, bytecodes, signals, delivers, deferrals, reached.size());
    }

    /**
     * The signal classes the entries hand the job: each reachable {@code getstatic} or
     * {@code getfield} of a field whose type is an AbortSignal class; for an interface-typed static
     * field, the class its owner's static initialiser stores into it.
     */
    List<String> signals(Collection<ClassPool.Owned> entries) {
        Set<String> out = new LinkedHashSet<>();
        for (ClassPool.Owned e : entries) {
            AbstractInsnNode[] insns = e.method().instructions.toArray();
            BitSet reachable = Reachable.of(e.method(), known);
            for (int i = 0; i < insns.length; i++) {
                if (reachable.get(i) && insns[i] instanceof FieldInsnNode f
                        && (f.getOpcode() == Opcodes.GETSTATIC || f.getOpcode() == Opcodes.GETFIELD) && f.desc.startsWith("L")) {
                    String type = Type.getType(f.desc).getInternalName();
                    if (!pool.isSubtype(type, SIGNAL)) {
                        continue;
                    }
                    ClassNode t = pool.get(type);
                    if (t != null && (t.access & Opcodes.ACC_INTERFACE) == 0) {
                        out.add(type);
                    } else if (f.getOpcode() == Opcodes.GETSTATIC) {
                        out.addAll(storedBy(f.owner, f.name));
                    }
                }
            }
        }
        return new ArrayList<>(out);
    }

    /** The classes instantiated in {@code owner}'s static initialiser and stored into its field {@code field}. */
    private List<String> storedBy(String owner, String field) {
        List<String> out = new ArrayList<>();
        ClassNode c = pool.get(owner);
        if (c == null) {
            return out;
        }
        for (MethodNode m : c.methods) {
            if (!m.name.equals("<clinit>")) {
                continue;
            }
            String last = null;
            for (AbstractInsnNode n : m.instructions.toArray()) {
                if (n instanceof TypeInsnNode t && t.getOpcode() == Opcodes.NEW) {
                    last = t.desc;
                } else if (n instanceof FieldInsnNode f && f.getOpcode() == Opcodes.PUTSTATIC && f.name.equals(field)
                        && last != null) {
                    out.add(last);
                }
            }
        }
        return out;
    }

    /** Whether the signal's {@code abortRequested()} reaches a delivery point ({@code Atc.poll}). */
    boolean signalDelivers(String signal) {
        ClassPool.Owned m = pool.resolve(signal, "abortRequested", "()Z");
        return m != null && reachesDelivery(m, new HashSet<>());
    }

    private boolean reachesDelivery(ClassPool.Owned m, Set<String> seen) {
        if (!seen.add(m.key())) {
            return false;
        }
        for (AbstractInsnNode n : m.method().instructions.toArray()) {
            if (n instanceof MethodInsnNode c) {
                if (c.owner.equals(DELIVERY_OWNER) && c.name.equals("poll")) {
                    return true;
                }
                for (ClassPool.Owned t : targets(c)) {
                    if (reachesDelivery(t, seen)) {
                        return true;
                    }
                }
            }
        }
        return false;
    }

    /** Every followed method reachable from the entries, over the reachable instructions. */
    private Set<ClassPool.Owned> reached(Collection<ClassPool.Owned> entries) {
        Set<ClassPool.Owned> out = new LinkedHashSet<>();
        Set<String> seen = new HashSet<>();
        Deque<ClassPool.Owned> work = new ArrayDeque<>(entries);
        while (!work.isEmpty()) {
            ClassPool.Owned m = work.poll();
            if (!seen.add(m.key())) {
                continue;
            }
            out.add(m);
            AbstractInsnNode[] insns = m.method().instructions.toArray();
            BitSet reachable = Reachable.of(m.method(), known);
            for (int i = 0; i < insns.length; i++) {
                if (reachable.get(i) && insns[i] instanceof MethodInsnNode c && !c.name.equals("abortRequested")) {
                    work.addAll(targets(c));
                }
            }
        }
        return out;
    }

    /** The synchronized blocks and methods of the job that can run: RTSJ defers an AIE inside them. */
    private List<String> monitorRegions(Set<ClassPool.Owned> reached) {
        List<String> out = new ArrayList<>();
        for (ClassPool.Owned m : reached) {
            String name = m.owner().name.replace('/', '.') + "." + m.method().name;
            if ((m.method().access & Opcodes.ACC_SYNCHRONIZED) != 0) {
                out.add(name + ": synchronized method (its monitor held while it runs): RTSJ defers the AIE to its return");
            }
            AbstractInsnNode[] insns = m.method().instructions.toArray();
            BitSet reachable = Reachable.of(m.method(), known);
            for (int i = 0; i < insns.length; i++) {
                if (reachable.get(i) && insns[i].getOpcode() == Opcodes.MONITORENTER) {
                    out.add(name + ":" + Lines.of(insns[i]) + ": synchronized block (a monitor held while the code in it "
                            + "runs, the calls it makes included): RTSJ defers the AIE to its exit");
                }
            }
        }
        return out;
    }

    /**
     * The bytecodes of one particle step of a loop: the loop body's instructions and, for each call
     * in it, every instruction of the followed callee and its callees (each once; inner loops
     * counted once per step, calls already on the path not again).
     */
    long stepBytecodes(AbortPollCheck.LoopGap l) {
        AbstractInsnNode[] insns = l.method().method().instructions.toArray();
        long n = 0;
        Set<String> path = new HashSet<>();
        path.add(l.method().key());
        for (int i = l.from(); i <= l.to(); i++) {
            if (insns[i].getOpcode() < 0) {
                continue;
            }
            n++;
            if (insns[i] instanceof MethodInsnNode c && !c.name.equals("abortRequested")) {
                n += callees(c, path);
            }
        }
        return n;
    }

    private long callees(MethodInsnNode c, Set<String> path) {
        long most = 0;
        for (ClassPool.Owned t : targets(c)) {
            most = Math.max(most, size(t, path));
        }
        return most;
    }

    private long size(ClassPool.Owned m, Set<String> path) {
        if (!path.add(m.key())) {
            return 0;
        }
        long n = 0;
        for (AbstractInsnNode i : m.method().instructions.toArray()) {
            if (i.getOpcode() >= 0) {
                n++;
                if (i instanceof MethodInsnNode c) {
                    n += callees(c, path);
                }
            }
        }
        path.remove(m.key());
        return n;
    }

    private List<ClassPool.Owned> targets(MethodInsnNode c) {
        List<ClassPool.Owned> all = c.getOpcode() == Opcodes.INVOKEVIRTUAL || c.getOpcode() == Opcodes.INVOKEINTERFACE
                ? pool.implementations(c.owner, c.name, c.desc)
                : single(pool.resolve(c.owner, c.name, c.desc));
        return all.stream().filter(t -> follow.test(t.owner().name) && t.method().instructions.size() > 0).toList();
    }

    private static List<ClassPool.Owned> single(ClassPool.Owned o) {
        return o == null ? List.of() : List.of(o);
    }
}
