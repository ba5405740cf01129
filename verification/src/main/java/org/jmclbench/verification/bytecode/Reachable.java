package org.jmclbench.verification.bytecode;

import java.util.ArrayDeque;
import java.util.BitSet;
import java.util.Deque;
import java.util.Map;

import org.objectweb.asm.Opcodes;
import org.objectweb.asm.Type;
import org.objectweb.asm.tree.AbstractInsnNode;
import org.objectweb.asm.tree.FieldInsnNode;
import org.objectweb.asm.tree.JumpInsnNode;
import org.objectweb.asm.tree.LabelNode;
import org.objectweb.asm.tree.LookupSwitchInsnNode;
import org.objectweb.asm.tree.MethodInsnNode;
import org.objectweb.asm.tree.MethodNode;
import org.objectweb.asm.tree.TableSwitchInsnNode;
import org.objectweb.asm.tree.TryCatchBlockNode;

/**
 * The instructions of a method that can run when some enum values are known: a reference
 * comparison of a field of an enum type with one of its constants ({@code design ==
 * RtsjDesign.THESIS}) goes the one way the known value decides; every other branch, switch and
 * exception handler is followed both ways. So one engine's code that chooses its design at run
 * time is analysed for one design at a time.
 */
final class Reachable {
    private Reachable() {
    }

    /** The code-order indices of the instructions that can run, given {@code known} (enum internal name to constant name). */
    static BitSet of(MethodNode m, Map<String, String> known) {
        AbstractInsnNode[] insns = m.instructions.toArray();
        BitSet out = new BitSet(insns.length);
        Deque<Integer> work = new ArrayDeque<>();
        if (insns.length > 0) {
            work.push(0);
        }
        boolean grew = true;
        while (grew) {
            while (!work.isEmpty()) {
                int i = work.pop();
                if (i >= insns.length || out.get(i)) {
                    continue;
                }
                out.set(i);
                successors(m, insns, i, known, work);
            }
            grew = false;
            // A handler runs when an instruction of its range can throw, as far as this walk knows: any reachable one.
            if (m.tryCatchBlocks != null) {
                for (TryCatchBlockNode t : m.tryCatchBlocks) {
                    int h = m.instructions.indexOf(t.handler);
                    int from = m.instructions.indexOf(t.start);
                    int to = m.instructions.indexOf(t.end);
                    if (!out.get(h) && out.nextSetBit(from) >= 0 && out.nextSetBit(from) < to) {
                        work.push(h);
                        grew = true;
                    }
                }
            }
        }
        return out;
    }

    private static void successors(MethodNode m, AbstractInsnNode[] insns, int i, Map<String, String> known,
                                   Deque<Integer> work) {
        AbstractInsnNode n = insns[i];
        int op = n.getOpcode();
        if (n instanceof JumpInsnNode j) {
            int target = m.instructions.indexOf(j.label);
            Boolean equal = knownComparison(insns, i, known);
            if (op == Opcodes.GOTO) {
                work.push(target);
            } else if (equal == null) {
                work.push(target);
                work.push(i + 1);
            } else {
                boolean jumps = op == Opcodes.IF_ACMPEQ ? equal : !equal;
                work.push(jumps ? target : i + 1);
            }
        } else if (n instanceof TableSwitchInsnNode t) {
            push(m, t.dflt, work);
            t.labels.forEach(l -> push(m, l, work));
        } else if (n instanceof LookupSwitchInsnNode t) {
            push(m, t.dflt, work);
            t.labels.forEach(l -> push(m, l, work));
        } else if (!(op >= Opcodes.IRETURN && op <= Opcodes.RETURN) && op != Opcodes.ATHROW) {
            work.push(i + 1);
        }
    }

    private static void push(MethodNode m, LabelNode l, Deque<Integer> work) {
        work.push(m.instructions.indexOf(l));
    }

    /**
     * For {@code if_acmpeq}/{@code if_acmpne} whose operands are a value of a known enum type (a
     * field read, or a call returning it such as javac's accessor of an outer class's field) and a
     * read of one of its constants, in either order: whether they are equal; else null.
     */
    private static Boolean knownComparison(AbstractInsnNode[] insns, int jump, Map<String, String> known) {
        int op = insns[jump].getOpcode();
        if (op != Opcodes.IF_ACMPEQ && op != Opcodes.IF_ACMPNE) {
            return null;
        }
        int b = previous(insns, jump);
        int a = b < 0 ? -1 : previous(insns, b);
        if (a < 0) {
            return null;
        }
        FieldInsnNode constant = constantOf(insns[b], known);
        AbstractInsnNode value = insns[a];
        if (constant == null) {
            constant = constantOf(insns[a], known);
            value = insns[b];
        }
        if (constant == null || !pushes(value, constant.desc) || constantOf(value, known) != null) {
            return null;
        }
        return known.get(constant.owner).equals(constant.name);
    }

    /** The read of a constant of a known enum ({@code getstatic E.C : E}), or null. */
    private static FieldInsnNode constantOf(AbstractInsnNode n, Map<String, String> known) {
        return n instanceof FieldInsnNode f && f.getOpcode() == Opcodes.GETSTATIC && known.containsKey(f.owner)
                && f.desc.equals("L" + f.owner + ";") ? f : null;
    }

    /** Whether the instruction pushes one value of type {@code desc}: a field read or a call returning it. */
    private static boolean pushes(AbstractInsnNode n, String desc) {
        if (n instanceof FieldInsnNode f) {
            return (f.getOpcode() == Opcodes.GETFIELD || f.getOpcode() == Opcodes.GETSTATIC) && f.desc.equals(desc);
        }
        return n instanceof MethodInsnNode m && Type.getReturnType(m.desc).getDescriptor().equals(desc);
    }

    /** The instruction before i that changes the stack: labels, frames and static {@code ()V} calls (a delivery point) skipped. */
    private static int previous(AbstractInsnNode[] insns, int i) {
        for (int k = i - 1; k >= 0; k--) {
            AbstractInsnNode n = insns[k];
            if (n.getOpcode() < 0 || n instanceof MethodInsnNode m && m.getOpcode() == Opcodes.INVOKESTATIC && m.desc.equals("()V")) {
                continue;
            }
            return k;
        }
        return -1;
    }
}
