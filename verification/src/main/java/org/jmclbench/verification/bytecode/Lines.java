package org.jmclbench.verification.bytecode;

import org.objectweb.asm.tree.AbstractInsnNode;
import org.objectweb.asm.tree.LineNumberNode;

/** Source lines of bytecode instructions. */
final class Lines {
    private Lines() {}

    /** The line of the nearest line-number entry at or before the instruction (0 if none). */
    static int of(AbstractInsnNode insn) {
        // A label that starts a line (a loop head) carries that line's entry right after it.
        for (AbstractInsnNode n = insn; n != null && n.getOpcode() < 0; n = n.getNext()) {
            if (n instanceof LineNumberNode ln) {
                return ln.line;
            }
        }
        for (AbstractInsnNode n = insn; n != null; n = n.getPrevious()) {
            if (n instanceof LineNumberNode ln) {
                return ln.line;
            }
        }
        // An instruction before the first entry (a loop head label): the next entry's line.
        for (AbstractInsnNode n = insn; n != null; n = n.getNext()) {
            if (n instanceof LineNumberNode ln) {
                return ln.line;
            }
        }
        return 0;
    }
}
