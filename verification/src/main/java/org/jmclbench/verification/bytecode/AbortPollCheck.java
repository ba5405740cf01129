package org.jmclbench.verification.bytecode;

import org.objectweb.asm.Opcodes;
import org.objectweb.asm.Type;
import org.objectweb.asm.tree.AbstractInsnNode;
import org.objectweb.asm.tree.ClassNode;
import org.objectweb.asm.tree.FieldInsnNode;
import org.objectweb.asm.tree.IincInsnNode;
import org.objectweb.asm.tree.IntInsnNode;
import org.objectweb.asm.tree.JumpInsnNode;
import org.objectweb.asm.tree.LdcInsnNode;
import org.objectweb.asm.tree.LocalVariableNode;
import org.objectweb.asm.tree.MethodInsnNode;
import org.objectweb.asm.tree.MethodNode;
import org.objectweb.asm.tree.VarInsnNode;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.BitSet;
import java.util.Collection;
import java.util.Deque;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.function.Predicate;

/**
 * Static P4: after an abort request, terminable job code runs at most one poll interval of
 * particle steps before it polls.
 *
 * <p>Terminable job code is every method of the project that takes an abort signal (a parameter
 * whose type's simple name is {@code AbortSignal}) and every method they call, followed into the
 * classes {@code follow} accepts (static and special calls to the method the JVM resolves,
 * virtual and interface calls to every override in the pool). A loop is a backward jump; its
 * body runs from the jump's target to the jump. A particle loop is a loop whose head does not
 * compare its counter with a constant ({@code i < 6}, a covariance's six terms, is not).
 *
 * <p>Each poll ({@code abortRequested()Z}) has a stride, the most iterations of its loop from
 * one poll to the next, read from the guard that skips it: none, 1; {@code (i & M) == 0}, M + 1;
 * {@code i % K == 0}, K. M and K are evaluated from constants and the configured mask (a
 * variable or field named {@code pollMask}, worth interval - 1), so {@code (i & pollMask)} has
 * the interval as its stride and {@code (i & ((pollMask << 2) | 3))} four intervals. A guard it
 * cannot evaluate is reported. A particle loop is fine when a poll in its body has a stride of
 * at most the interval, or when it sits in a block loop that polls once per iteration, outside
 * its other inner loops, and steps its counter by at most the interval, and the inner loop starts
 * afresh in each block (a local its exit test reads is set in the block loop outside it; else it
 * is a walk that may pass every particle in one block). Code that runs inside a
 * particle loop (an inner loop, or a method called from that loop's body) is part of one particle
 * step and is not held to the rule. Every other particle loop is reported at the line of its
 * head: after an abort request it may run more than an interval of particles.
 *
 * <p>What this bounds: every particle loop of a job polls at its first iteration (its counter
 * starts at a multiple of the stride) and at least every interval after, so the particle steps
 * between two polls are at most the interval within a loop, and at most the tail of one loop
 * plus the head of the next across two (code between loops is a constant number of steps).
 *
 * <p>The same walk gives each particle loop's gap ({@link #gaps}): the most particle steps it
 * runs between two polls, which {@link AbortBound} turns into a bound on abort latency. Which
 * calls count as polls and which enum values are known (branches on them followed one way) can
 * be set, so that a delivery point of RTSJ's ATC, or a design chosen by an enum, is analysed alike.
 */
public final class AbortPollCheck {
    /** The stride of a poll whose guard the rule cannot evaluate; also the gap of a loop that does not poll. */
    public static final long UNKNOWN = Long.MAX_VALUE;

    private final ClassPool pool;
    private final Predicate<String> follow;
    private final int interval;
    private final String signalSimpleName;
    private Predicate<MethodInsnNode> pollCall = c -> c.name.equals("abortRequested") && c.desc.equals("()Z");
    private Map<String, String> known = Map.of();

    /**
     * One particle loop of terminable job code: where it is, the most particle steps it may run
     * between two polls ({@link #UNKNOWN}: it may run whole without one) and, when that is more
     * than the interval, why.
     */
    public record LoopGap(ClassPool.Owned method, int from, int to, int line, long steps, String problem) {
        /** {@code Class.method:line}. */
        public String where() {
            return method.owner().name.replace('/', '.') + "." + method.method().name + ":" + line;
        }
    }

    /** Every class of the pool, interval 64, signal type {@code AbortSignal}. */
    public AbortPollCheck(ClassPool pool) {
        this(pool, c -> true, 64);
    }

    /**
     * @param follow   which classes (internal names) hold job code: entries and followed callees
     * @param interval the configured poll interval, in particle steps (a power of two)
     */
    public AbortPollCheck(ClassPool pool, Predicate<String> follow, int interval) {
        this.pool = pool;
        this.follow = follow;
        this.interval = interval;
        this.signalSimpleName = "AbortSignal";
    }

    /** Which calls are polls (default: {@code abortRequested()Z}). */
    public AbortPollCheck polls(Predicate<MethodInsnNode> isPoll) {
        this.pollCall = isPoll;
        return this;
    }

    /** Enum values known for the analysis (enum internal name to constant): a comparison with one goes one way. */
    public AbortPollCheck known(Map<String, String> values) {
        this.known = values;
        return this;
    }

    /** Every particle loop of terminable job code that does not poll within the interval. */
    public List<Violation> check() {
        List<ClassPool.Owned> entries = new ArrayList<>();
        for (ClassNode c : pool.all()) {
            if (!follow.test(c.name)) {
                continue;
            }
            for (MethodNode m : c.methods) {
                if (terminable(m) && m.instructions.size() > 0) {
                    entries.add(new ClassPool.Owned(c, m));
                }
            }
        }
        List<Violation> out = new ArrayList<>();
        for (LoopGap g : gaps(entries)) {
            if (g.problem() != null) {
                out.add(new Violation(g.method().owner().name.replace('/', '.'), g.method().method().name, g.line(),
                        g.problem()));
            }
        }
        return out;
    }

    /** The gap of every particle loop of the job code reached from {@code entries} (not of loops inside a step). */
    public List<LoopGap> gaps(Collection<ClassPool.Owned> entries) {
        List<LoopGap> out = new ArrayList<>();
        Set<String> seen = new HashSet<>();
        Deque<Reached> work = new ArrayDeque<>();
        for (ClassPool.Owned e : entries) {
            if (seen.add(key(e.owner(), e.method(), false))) {
                work.add(new Reached(e, false));
            }
        }
        while (!work.isEmpty()) {
            Reached r = work.poll();
            checkMethod(r, out, seen, work);
        }
        return out;
    }

    private boolean terminable(MethodNode m) {
        for (Type t : Type.getArgumentTypes(m.desc)) {
            if (t.getSort() == Type.OBJECT) {
                String n = t.getClassName();
                String simple = n.substring(Math.max(n.lastIndexOf('.'), n.lastIndexOf('$')) + 1);
                if (simple.equals(signalSimpleName)) {
                    return true;
                }
            }
        }
        return false;
    }

    private static String key(ClassNode c, MethodNode m, boolean inStep) {
        return c.name + "." + m.name + m.desc + (inStep ? "#step" : "");
    }

    private void checkMethod(Reached r, List<LoopGap> out, Set<String> seen, Deque<Reached> work) {
        MethodNode m = r.m().method();
        AbstractInsnNode[] insns = m.instructions.toArray();
        BitSet reachable = Reachable.of(m, known);
        List<int[]> loops = new ArrayList<>();
        List<Poll> polls = new ArrayList<>();
        for (int i = 0; i < insns.length; i++) {
            if (!reachable.get(i)) {
                continue;
            }
            if (insns[i] instanceof JumpInsnNode j) {
                int target = m.instructions.indexOf(j.label);
                if (target <= i) {
                    loops.add(new int[] {target, i});
                }
            } else if (insns[i] instanceof MethodInsnNode call && pollCall.test(call)) {
                polls.add(new Poll(i, stride(m, insns, i)));
            }
        }
        List<int[]> particleLoops = new ArrayList<>();
        for (int[] loop : loops) {
            if (!constantBound(insns, loop)) {
                particleLoops.add(loop);
            }
        }
        if (!r.inStep()) {
            for (int[] loop : particleLoops) {
                Gap g = gap(m, insns, loop, loops, polls);
                out.add(new LoopGap(r.m(), loop[0], loop[1], Lines.of(insns[loop[0]]), g.steps(), g.problem()));
            }
        }
        for (int i = 0; i < insns.length; i++) {
            if (!reachable.get(i) || !(insns[i] instanceof MethodInsnNode call) || pollCall.test(call)) {
                continue;
            }
            boolean inStep = r.inStep();
            for (int[] loop : particleLoops) {
                inStep |= inside(i, loop);
            }
            List<ClassPool.Owned> targets = call.getOpcode() == Opcodes.INVOKEVIRTUAL
                    || call.getOpcode() == Opcodes.INVOKEINTERFACE
                    ? pool.implementations(call.owner, call.name, call.desc)
                    : single(pool.resolve(call.owner, call.name, call.desc));
            for (ClassPool.Owned t : targets) {
                if (follow.test(t.owner().name) && t.method().instructions.size() > 0
                        && seen.add(key(t.owner(), t.method(), inStep))) {
                    work.add(new Reached(t, inStep));
                }
            }
        }
    }

    /** The loop's gap and why it may run past the interval without a poll (null when it cannot). */
    private Gap gap(MethodNode m, AbstractInsnNode[] insns, int[] loop, List<int[]> loops, List<Poll> polls) {
        long best = UNKNOWN;
        boolean any = false;
        for (Poll p : polls) {
            if (inside(p.at(), loop)) {
                any = true;
                // A poll in a nested loop runs each time that loop runs: it bounds this loop only
                // as an inner poll does (once per iteration at most), so count it as stride 1
                // only when it is directly in this loop's body.
                best = Math.min(best, directlyIn(p.at(), loop, loops) ? p.stride() : 1);
            }
        }
        if (any) {
            if (best == UNKNOWN) {
                return new Gap(UNKNOWN, "loop polls abortRequested() behind a guard whose stride cannot be read");
            }
            return new Gap(best, best <= interval ? null
                    : "loop polls abortRequested() every " + best + " particle steps, more than the poll interval "
                            + interval);
        }
        // A block loop around it that polls outside its other nested loops, one block per iteration.
        for (int[] outer : loops) {
            if (outer == loop || !contains(outer, loop)) {
                continue;
            }
            for (Poll p : polls) {
                if (inside(p.at(), outer) && directlyIn(p.at(), outer, loops)) {
                    String walked = carriedCounter(m, insns, loop, outer);
                    if (walked != null) {
                        return new Gap(UNKNOWN, "loop goes on from where the block loop's previous iteration left " + walked
                                + " (it is not set again there): one block may walk every particle between two polls");
                    }
                    long block = counterStep(insns, outer);
                    return new Gap(block, block <= interval ? null
                            : "loop runs a block of " + (block == UNKNOWN ? "an unknown number of" : block)
                                    + " particle steps between its block loop's polls, more than the poll interval "
                                    + interval);
                }
            }
        }
        return new Gap(UNKNOWN, "loop does not poll abortRequested() (terminable job code)");
    }

    /**
     * A local that {@code loop}'s exit test reads and its body changes, but that the block loop
     * {@code outer} does not set outside it: the loop carries on where the block's previous
     * iteration left it (systematic resampling's walk as an inner while), so its iterations in one
     * block are not bounded by the block. Its name (or "local N"), else null.
     */
    private static String carriedCounter(MethodNode m, AbstractInsnNode[] insns, int[] loop, int[] outer) {
        Set<Integer> tested = new HashSet<>();
        for (int i = loop[0]; i <= loop[1]; i++) {
            if (insns[i] instanceof JumpInsnNode j && j.getOpcode() != Opcodes.GOTO
                    && !inside(m.instructions.indexOf(j.label), loop)) {
                for (int k = i - 1; k >= loop[0] && !(insns[k] instanceof JumpInsnNode); k--) {
                    if (insns[k].getOpcode() == Opcodes.ILOAD) {
                        tested.add(((VarInsnNode) insns[k]).var);
                    }
                }
            }
        }
        for (int v : tested) {
            int set = sets(insns, loop[0], loop[1], v);
            if (set >= 0 && !setsOutside(insns, outer, loop, v)) {
                String name = localName(m, v, insns[set]);
                return name != null ? name : "local " + v;
            }
        }
        return null;
    }

    /** The first instruction in [from, to] that stores into or increments local {@code var}, else -1. */
    private static int sets(AbstractInsnNode[] insns, int from, int to, int var) {
        for (int i = from; i <= to; i++) {
            if (insns[i] instanceof IincInsnNode inc && inc.var == var
                    || insns[i].getOpcode() == Opcodes.ISTORE && ((VarInsnNode) insns[i]).var == var) {
                return i;
            }
        }
        return -1;
    }

    private static boolean setsOutside(AbstractInsnNode[] insns, int[] outer, int[] loop, int var) {
        return sets(insns, outer[0], loop[0] - 1, var) >= 0 || sets(insns, loop[1] + 1, outer[1], var) >= 0;
    }

    /** True when the instruction is in the loop's body and in no loop nested in it. */
    private static boolean directlyIn(int at, int[] loop, List<int[]> loops) {
        if (!inside(at, loop)) {
            return false;
        }
        for (int[] other : loops) {
            if (other != loop && contains(loop, other) && inside(at, other)) {
                return false;
            }
        }
        return true;
    }

    /** The constant a loop adds to its counter ({@code iinc v k} at its end, k > 0), else UNKNOWN. */
    private static long counterStep(AbstractInsnNode[] insns, int[] loop) {
        for (int i = loop[1]; i >= loop[0]; i--) {
            if (insns[i] instanceof IincInsnNode inc) {
                return inc.incr > 0 ? inc.incr : UNKNOWN;
            }
            if (insns[i].getOpcode() >= 0 && !(insns[i] instanceof JumpInsnNode)) {
                break;
            }
        }
        return UNKNOWN;
    }

    /**
     * The poll's stride, from the conditional jump just before it that skips it: none, 1;
     * {@code x & M} tested against zero, M + 1; {@code x % K}, K; otherwise UNKNOWN.
     */
    private long stride(MethodNode m, AbstractInsnNode[] insns, int poll) {
        int guard = -1;
        for (int i = poll - 1; i >= 0; i--) {
            if (insns[i] instanceof JumpInsnNode) {
                guard = i;
                break;
            }
            if (insns[i].getOpcode() >= 0 && !loadsSignal(insns[i])) {
                return 1; // something else is computed between: no guard of this poll
            }
        }
        if (guard < 0) {
            return 1;
        }
        JumpInsnNode j = (JumpInsnNode) insns[guard];
        int target = m.instructions.indexOf(j.label);
        if (target <= poll || (j.getOpcode() != Opcodes.IFNE && j.getOpcode() != Opcodes.IFEQ)) {
            return 1; // not a jump over the poll (a loop head, an earlier condition)
        }
        int op = previous(insns, guard);
        if (op < 0 || (insns[op].getOpcode() != Opcodes.IAND && insns[op].getOpcode() != Opcodes.IREM)) {
            return UNKNOWN;
        }
        Long operand = rightOperand(m, insns, op);
        if (operand == null || operand <= 0 && insns[op].getOpcode() == Opcodes.IREM || operand < 0) {
            return UNKNOWN;
        }
        return insns[op].getOpcode() == Opcodes.IAND ? operand + 1 : operand;
    }

    /** The instructions that load the signal before the call: {@code aload}, {@code getfield}. */
    private static boolean loadsSignal(AbstractInsnNode insn) {
        return insn.getOpcode() == Opcodes.ALOAD || insn.getOpcode() == Opcodes.GETFIELD
                || insn.getOpcode() == Opcodes.GETSTATIC;
    }

    private static int previous(AbstractInsnNode[] insns, int i) {
        for (int k = i - 1; k >= 0; k--) {
            if (insns[k].getOpcode() >= 0) {
                return k;
            }
        }
        return -1;
    }

    /**
     * The value of the second operand of the binary instruction at {@code op}, evaluated over
     * constants, the configured mask and {@code + - * << >> | ^}; null when it is anything else.
     */
    private Long rightOperand(MethodNode m, AbstractInsnNode[] insns, int op) {
        // Walk back to where the second operand's expression starts (one value on the stack).
        int need = 1;
        int start = op;
        while (need > 0) {
            start = previous(insns, start);
            if (start < 0) {
                return null;
            }
            int code = insns[start].getOpcode();
            if (isBinary(code)) {
                need += 1;
            } else if (pushesOne(insns[start])) {
                need -= 1;
            } else if (code == Opcodes.GETFIELD) {
                // consumes the object, pushes the field: no change
            } else {
                return null;
            }
        }
        Deque<Long> stack = new ArrayDeque<>();
        for (int i = start; i < op; i++) {
            AbstractInsnNode insn = insns[i];
            int code = insn.getOpcode();
            if (code < 0) {
                continue;
            }
            if (isBinary(code)) {
                long b = stack.pop();
                long a = stack.pop();
                stack.push(apply(code, a, b));
            } else if (code == Opcodes.GETFIELD) {
                stack.pop();
                stack.push(((FieldInsnNode) insn).name.equals("pollMask") ? (long) interval - 1 : Long.MIN_VALUE);
            } else {
                stack.push(value(m, insn, i, insns));
            }
        }
        long v = stack.pop();
        return v == Long.MIN_VALUE ? null : v;
    }

    private static boolean isBinary(int code) {
        return code == Opcodes.IADD || code == Opcodes.ISUB || code == Opcodes.IMUL || code == Opcodes.ISHL
                || code == Opcodes.ISHR || code == Opcodes.IUSHR || code == Opcodes.IOR || code == Opcodes.IXOR
                || code == Opcodes.IAND;
    }

    private static boolean pushesOne(AbstractInsnNode insn) {
        int code = insn.getOpcode();
        return (code >= Opcodes.ICONST_M1 && code <= Opcodes.ICONST_5) || code == Opcodes.BIPUSH
                || code == Opcodes.SIPUSH || code == Opcodes.ILOAD || code == Opcodes.ALOAD
                || (code == Opcodes.LDC && ((LdcInsnNode) insn).cst instanceof Integer);
    }

    private static long apply(int code, long a, long b) {
        if (a == Long.MIN_VALUE || b == Long.MIN_VALUE) {
            return Long.MIN_VALUE;
        }
        int x = (int) a;
        int y = (int) b;
        return switch (code) {
            case Opcodes.IADD -> x + y;
            case Opcodes.ISUB -> x - y;
            case Opcodes.IMUL -> x * y;
            case Opcodes.ISHL -> x << y;
            case Opcodes.ISHR -> x >> y;
            case Opcodes.IUSHR -> x >>> y;
            case Opcodes.IOR -> x | y;
            case Opcodes.IXOR -> x ^ y;
            default -> x & y;
        };
    }

    /** A pushed value: a constant, the configured mask, or Long.MIN_VALUE (unknown). */
    private long value(MethodNode m, AbstractInsnNode insn, int at, AbstractInsnNode[] insns) {
        int code = insn.getOpcode();
        if (code >= Opcodes.ICONST_M1 && code <= Opcodes.ICONST_5) {
            return code - Opcodes.ICONST_0;
        }
        if (code == Opcodes.BIPUSH || code == Opcodes.SIPUSH) {
            return ((IntInsnNode) insn).operand;
        }
        if (code == Opcodes.LDC) {
            return (Integer) ((LdcInsnNode) insn).cst;
        }
        if (code == Opcodes.ILOAD && "pollMask".equals(localName(m, ((VarInsnNode) insn).var, insn))) {
            return interval - 1;
        }
        return Long.MIN_VALUE;
    }

    /** The name of local variable {@code var} where {@code insn} reads it (needs javac's -g). */
    private static String localName(MethodNode m, int var, AbstractInsnNode insn) {
        if (m.localVariables == null) {
            return null;
        }
        int at = m.instructions.indexOf(insn);
        for (LocalVariableNode v : m.localVariables) {
            if (v.index == var && m.instructions.indexOf(v.start) <= at && at <= m.instructions.indexOf(v.end)) {
                return v.name;
            }
        }
        return null;
    }

    /** True when the loop's head is {@code iload; <int constant>; if_icmpXX} (javac's bounded for). */
    private static boolean constantBound(AbstractInsnNode[] insns, int[] loop) {
        List<AbstractInsnNode> head = new ArrayList<>();
        for (int i = loop[0]; i <= loop[1] && head.size() < 3; i++) {
            if (insns[i].getOpcode() >= 0) {
                head.add(insns[i]);
            }
        }
        if (head.size() < 3 || head.get(0).getOpcode() != Opcodes.ILOAD) {
            return false;
        }
        int c = head.get(1).getOpcode();
        boolean constant = (c >= Opcodes.ICONST_M1 && c <= Opcodes.ICONST_5) || c == Opcodes.BIPUSH
                || c == Opcodes.SIPUSH;
        int j = head.get(2).getOpcode();
        return constant && j >= Opcodes.IF_ICMPEQ && j <= Opcodes.IF_ICMPLE;
    }

    private static List<ClassPool.Owned> single(ClassPool.Owned o) {
        return o == null ? List.of() : List.of(o);
    }

    private static boolean inside(int i, int[] loop) {
        return i >= loop[0] && i <= loop[1];
    }

    private static boolean contains(int[] outer, int[] inner) {
        return outer[0] <= inner[0] && inner[1] <= outer[1] && (outer[0] != inner[0] || outer[1] != inner[1]);
    }

    private record Poll(int at, long stride) {
    }

    private record Gap(long steps, String problem) {
    }

    private record Reached(ClassPool.Owned m, boolean inStep) {
    }
}
