package org.jmclbench.verification.bytecode;

import org.objectweb.asm.Opcodes;
import org.objectweb.asm.Type;
import org.objectweb.asm.tree.AbstractInsnNode;
import org.objectweb.asm.tree.ClassNode;
import org.objectweb.asm.tree.JumpInsnNode;
import org.objectweb.asm.tree.MethodInsnNode;
import org.objectweb.asm.tree.MethodNode;

import java.util.ArrayList;
import java.util.List;

/**
 * Static P4: every particle loop of terminable job code polls the abort request.
 *
 * <p>Precisely: terminable job code is every method of the project that takes an abort signal
 * (a parameter whose type's simple name is {@code AbortSignal}). A loop is a backward jump in
 * its bytecode; its body is the instructions from the jump's target to the jump. A loop polls
 * when its body calls {@code abortRequested()Z}. A loop that does not poll is still fine inside
 * an enclosing loop that polls directly, outside any other loop nested in it (the block loop
 * that polls once per block of particles). A loop whose head compares its counter with a
 * constant ({@code for (i = 0; i < 6; i++)}, over a covariance's six terms) is not a particle
 * loop and is left alone. Every other loop is reported, at the line of its head: after an abort
 * request it may run all its particles before the job notices.
 */
public final class AbortPollCheck {
    private final ClassPool pool;
    private final String signalSimpleName;

    public AbortPollCheck(ClassPool pool) {
        this(pool, "AbortSignal");
    }

    public AbortPollCheck(ClassPool pool, String signalSimpleName) {
        this.pool = pool;
        this.signalSimpleName = signalSimpleName;
    }

    /** Every loop of terminable job code that does not poll. */
    public List<Violation> check() {
        List<Violation> out = new ArrayList<>();
        for (ClassNode c : pool.all()) {
            for (MethodNode m : c.methods) {
                if (terminable(m)) {
                    checkMethod(c, m, out);
                }
            }
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

    private void checkMethod(ClassNode c, MethodNode m, List<Violation> out) {
        AbstractInsnNode[] insns = m.instructions.toArray();
        List<int[]> loops = new ArrayList<>();
        List<Integer> polls = new ArrayList<>();
        for (int i = 0; i < insns.length; i++) {
            if (insns[i] instanceof JumpInsnNode j) {
                int target = m.instructions.indexOf(j.label);
                if (target <= i) {
                    loops.add(new int[] {target, i});
                }
            } else if (insns[i] instanceof MethodInsnNode call && call.name.equals("abortRequested")
                    && call.desc.equals("()Z")) {
                polls.add(i);
            }
        }
        for (int[] loop : loops) {
            if (!constantBound(insns, loop) && !polled(loop, loops, polls)) {
                out.add(new Violation(c.name.replace('/', '.'), m.name, Lines.of(insns[loop[0]]),
                        "loop does not poll abortRequested() (terminable: takes an " + signalSimpleName + ")"));
            }
        }
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

    private static boolean polled(int[] loop, List<int[]> loops, List<Integer> polls) {
        for (int p : polls) {
            if (inside(p, loop)) {
                return true;
            }
        }
        // A block loop around it that polls outside its other nested loops.
        for (int[] outer : loops) {
            if (outer == loop || !contains(outer, loop)) {
                continue;
            }
            for (int p : polls) {
                if (!inside(p, outer)) {
                    continue;
                }
                boolean direct = true;
                for (int[] other : loops) {
                    if (other != outer && contains(outer, other) && inside(p, other) && !contains(other, loop)) {
                        direct = false;
                        break;
                    }
                }
                if (direct) {
                    return true;
                }
            }
        }
        return false;
    }

    private static boolean inside(int i, int[] loop) {
        return i >= loop[0] && i <= loop[1];
    }

    private static boolean contains(int[] outer, int[] inner) {
        return outer[0] <= inner[0] && inner[1] <= outer[1] && (outer[0] != inner[0] || outer[1] != inner[1]);
    }
}
