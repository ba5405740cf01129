package org.jmclbench.rtsj.weaver;

import java.util.ArrayDeque;
import java.util.Arrays;
import java.util.BitSet;
import java.util.Deque;
import java.util.HashMap;
import java.util.HashSet;
import java.util.Map;
import java.util.Set;
import java.util.function.IntPredicate;
import org.objectweb.asm.Opcodes;
import org.objectweb.asm.tree.AbstractInsnNode;
import org.objectweb.asm.tree.InsnList;
import org.objectweb.asm.tree.JumpInsnNode;
import org.objectweb.asm.tree.LabelNode;
import org.objectweb.asm.tree.LineNumberNode;
import org.objectweb.asm.tree.LookupSwitchInsnNode;
import org.objectweb.asm.tree.MethodNode;
import org.objectweb.asm.tree.TableSwitchInsnNode;
import org.objectweb.asm.tree.TryCatchBlockNode;
import org.objectweb.asm.tree.VarInsnNode;

/**
 * Where in one method an AIE may not be delivered (RTSJ's ATC-deferred regions), computed from
 * its bytecode: instructions that run while a monitor is held (the monitor depth, by a data-flow
 * pass over the control-flow graph including exception edges) and the code of {@code finally}
 * blocks. javac inlines a finally body on every exit path, and only the catch-any handler's copy
 * is marked in the exception table; the copies share the finally's source lines, so every
 * instruction on a line of a finally handler's body is deferred too (conservative: code on such
 * a line gets no delivery point). Unreachable code is deferred. Fails on what it cannot analyse
 * (jsr/ret, inconsistent monitor depths, a finally without line numbers).
 */
final class MethodRegions {
    private final MethodNode method;
    private final String where;
    private final AbstractInsnNode[] insns;
    private final Map<AbstractInsnNode, Integer> index = new HashMap<>();
    private final int[] depthBefore;
    private final int[] line;
    private final BitSet finallyCode = new BitSet();
    /** A synchronized block's exception cleanup (release the monitor, rethrow): deferred to its rethrow. */
    private final BitSet cleanupCode = new BitSet();
    private final Set<Integer> finallyLines = new HashSet<>();

    MethodRegions(MethodNode method, String where) {
        this.method = method;
        this.where = where;
        InsnList list = method.instructions;
        this.insns = list.toArray();
        for (int i = 0; i < insns.length; i++) {
            index.put(insns[i], i);
        }
        depthBefore = new int[insns.length];
        Arrays.fill(depthBefore, -1);
        line = new int[insns.length];
        if ((method.access & Opcodes.ACC_SYNCHRONIZED) != 0) {
            Arrays.fill(depthBefore, 1); // the whole body holds the monitor
        } else if (insns.length > 0) {
            monitorDepths();
        }
        lines();
        finallyBlocks();
    }

    /** Whether an AIE may be delivered just before instruction i (and, for a call, just after it). */
    boolean deliverable(int i) {
        return depthBefore[i] == 0 && !cleanupCode.get(i) && !finallyCode.get(i) && !finallyLines.contains(line[i]);
    }

    /** {@link #deliverable(int)} without the finally rule (the weaver's seeded bug for tests). */
    boolean deliverableIgnoringFinally(int i) {
        return depthBefore[i] == 0 && !cleanupCode.get(i);
    }

    /**
     * The instructions where {@code deliverable} allows a delivery and that normal flow (a
     * fall-through or a branch, not an exception) reaches from one where it does not: the ends of
     * synchronized blocks and finally code. RTSJ delivers an AIE that became pending in there as
     * soon as control leaves it; without a delivery point at the exit it waited for the next call
     * or backward branch, and was lost when the method returned first to its doInterruptible.
     */
    BitSet deferralExits(IntPredicate deliverable) {
        BitSet exits = new BitSet();
        for (int p = 0; p < insns.length; p++) {
            AbstractInsnNode n = insns[p];
            int op = n.getOpcode();
            if (op < 0 || depthBefore[p] < 0 || deliverable.test(p)) {
                continue;
            }
            // javac ends neither a monitor region nor a finally with a switch
            if (n instanceof JumpInsnNode) {
                exit(nextReal(indexOf(((JumpInsnNode) n).label)), deliverable, exits);
            }
            boolean fallsThrough = n instanceof JumpInsnNode ? op != Opcodes.GOTO
                    : !(n instanceof TableSwitchInsnNode || n instanceof LookupSwitchInsnNode)
                    && !(op >= Opcodes.IRETURN && op <= Opcodes.RETURN) && op != Opcodes.ATHROW;
            if (fallsThrough) {
                exit(nextReal(p + 1), deliverable, exits);
            }
        }
        return exits;
    }

    private static void exit(int i, IntPredicate deliverable, BitSet exits) {
        if (i >= 0 && deliverable.test(i)) {
            exits.set(i);
        }
    }

    /** The instructions, in code order. */
    AbstractInsnNode[] instructions() {
        return insns;
    }

    /** The code-order index of a label (branch target). */
    int indexOf(AbstractInsnNode n) {
        return index.get(n);
    }

    private void monitorDepths() {
        Deque<Integer> work = new ArrayDeque<>();
        depthBefore[0] = 0;
        work.add(0);
        while (!work.isEmpty()) {
            int i = work.poll();
            AbstractInsnNode n = insns[i];
            int d = depthBefore[i];
            int op = n.getOpcode();
            if (op == Opcodes.JSR || op == Opcodes.RET) {
                throw new WeaveException(where + ": jsr/ret is not supported (compile for Java 7 or later)");
            }
            int after = d + (op == Opcodes.MONITORENTER ? 1 : 0) - (op == Opcodes.MONITOREXIT ? 1 : 0);
            if (after < 0) {
                throw new WeaveException(where + ": monitorexit without a monitor held at instruction " + i);
            }
            for (TryCatchBlockNode t : method.tryCatchBlocks) {
                if (indexOf(t.start) <= i && i < indexOf(t.end)) {
                    flow(indexOf(t.handler), d, work);
                    if (t.type == null) {
                        break; // a catch-any handler takes everything; later ones are not reached from here
                    }
                }
            }
            if (n instanceof JumpInsnNode) {
                flow(indexOf(((JumpInsnNode) n).label), after, work);
                if (op != Opcodes.GOTO) {
                    flow(i + 1, after, work);
                }
            } else if (n instanceof TableSwitchInsnNode) {
                TableSwitchInsnNode s = (TableSwitchInsnNode) n;
                flow(indexOf(s.dflt), after, work);
                for (LabelNode l : s.labels) {
                    flow(indexOf(l), after, work);
                }
            } else if (n instanceof LookupSwitchInsnNode) {
                LookupSwitchInsnNode s = (LookupSwitchInsnNode) n;
                flow(indexOf(s.dflt), after, work);
                for (LabelNode l : s.labels) {
                    flow(indexOf(l), after, work);
                }
            } else if (!(op >= Opcodes.IRETURN && op <= Opcodes.RETURN) && op != Opcodes.ATHROW) {
                flow(i + 1, after, work);
            }
        }
    }

    private void flow(int target, int depth, Deque<Integer> work) {
        if (target >= insns.length) {
            return;
        }
        if (depthBefore[target] == -1) {
            depthBefore[target] = depth;
            work.add(target);
        } else if (depthBefore[target] != depth) {
            throw new WeaveException(where + ": monitor depth " + depthBefore[target] + " and " + depth
                    + " meet at instruction " + target + "; not javac's structured locking");
        }
    }

    private void lines() {
        int current = -1;
        for (int i = 0; i < insns.length; i++) {
            if (insns[i] instanceof LineNumberNode) {
                current = ((LineNumberNode) insns[i]).line;
            }
            line[i] = current;
        }
    }

    /** Marks each finally handler's code (to its rethrow) and collects its source lines. */
    private void finallyBlocks() {
        Set<Integer> handlers = new HashSet<>();
        for (TryCatchBlockNode t : method.tryCatchBlocks) {
            if (t.type == null) {
                handlers.add(indexOf(t.handler));
            }
        }
        for (int h : handlers) {
            int first = nextReal(h);
            if (first < 0 || insns[first].getOpcode() != Opcodes.ASTORE) {
                continue;
            }
            int slot = ((VarInsnNode) insns[first]).var;
            int second = nextReal(first + 1);
            int third = second < 0 ? -1 : nextReal(second + 1);
            if (second >= 0 && insns[second].getOpcode() == Opcodes.ALOAD && third >= 0
                    && insns[third].getOpcode() == Opcodes.MONITOREXIT) {
                // the monitor's own cleanup of a synchronized block: the depths cover it up to the
                // monitorexit; its rethrow is no exit from the block where an AIE should replace it
                cleanupCode.set(h, rethrowOf(first, slot) + 1);
                continue;
            }
            int end = rethrowOf(first, slot);
            boolean anyLine = false;
            for (int i = h; i <= end; i++) {
                finallyCode.set(i);
                if (insns[i] instanceof LineNumberNode) {
                    finallyLines.add(((LineNumberNode) insns[i]).line);
                    anyLine = true;
                }
            }
            if (!anyLine) {
                throw new WeaveException(where + ": a finally block without line numbers; compile with -g:lines so that "
                        + "its inlined copies can be found");
            }
        }
    }

    private int rethrowOf(int from, int slot) {
        for (int i = from + 1; i < insns.length; i++) {
            if (insns[i].getOpcode() == Opcodes.ATHROW) {
                int prev = previousReal(i - 1);
                if (prev >= 0 && insns[prev].getOpcode() == Opcodes.ALOAD && ((VarInsnNode) insns[prev]).var == slot) {
                    return i;
                }
            }
        }
        throw new WeaveException(where + ": a catch-any handler that does not rethrow what it caught; not a finally");
    }

    private int nextReal(int from) {
        for (int i = from; i < insns.length; i++) {
            if (insns[i].getOpcode() >= 0) {
                return i;
            }
        }
        return -1;
    }

    private int previousReal(int from) {
        for (int i = from; i >= 0; i--) {
            if (insns[i].getOpcode() >= 0) {
                return i;
            }
        }
        return -1;
    }
}
