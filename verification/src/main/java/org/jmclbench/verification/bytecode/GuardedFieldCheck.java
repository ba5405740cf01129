package org.jmclbench.verification.bytecode;

import org.objectweb.asm.Opcodes;
import org.objectweb.asm.tree.AbstractInsnNode;
import org.objectweb.asm.tree.ClassNode;
import org.objectweb.asm.tree.FieldInsnNode;
import org.objectweb.asm.tree.FieldNode;
import org.objectweb.asm.tree.MethodNode;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.function.Predicate;

/**
 * Static P2: a field that a class guards with its monitor is guarded everywhere.
 *
 * <p>In every class {@code follow} accepts that has a synchronized instance method, a field that
 * is neither final nor volatile and is read or written in one of its synchronized methods is
 * guarded by the object's monitor; every other access to it (outside the constructors, which run
 * before the object is shared) is reported, at its line. A field that no synchronized method
 * touches is not guarded and is left alone: its confinement (one handler's thread) is the JPF
 * race searches' to check. This finds the lock a method forgot, on every input, where the race
 * searches see a race only on an input whose threads meet there.
 */
public final class GuardedFieldCheck {
    private final ClassPool pool;
    private final Predicate<String> follow;

    public GuardedFieldCheck(ClassPool pool, Predicate<String> follow) {
        this.pool = pool;
        this.follow = follow;
    }

    /** Every access to a guarded field outside its class's monitor. */
    public List<Violation> check() {
        List<Violation> out = new ArrayList<>();
        for (ClassNode c : pool.all()) {
            if (!follow.test(c.name) || !hasSynchronizedMethod(c)) {
                continue;
            }
            Map<String, Boolean> guarded = new HashMap<>();
            for (FieldNode f : c.fields) {
                if ((f.access & (Opcodes.ACC_FINAL | Opcodes.ACC_VOLATILE | Opcodes.ACC_STATIC)) == 0) {
                    guarded.put(f.name, false);
                }
            }
            for (MethodNode m : c.methods) {
                if (isSynchronized(m)) {
                    for (AbstractInsnNode insn : m.instructions) {
                        if (insn instanceof FieldInsnNode f && f.owner.equals(c.name) && guarded.containsKey(f.name)) {
                            guarded.put(f.name, true);
                        }
                    }
                }
            }
            for (ClassNode user : pool.all()) {
                if (!follow.test(user.name)) {
                    continue;
                }
                for (MethodNode m : user.methods) {
                    if (user == c && (isSynchronized(m) || m.name.equals("<init>"))) {
                        continue;
                    }
                    for (AbstractInsnNode insn : m.instructions) {
                        if (insn instanceof FieldInsnNode f && f.owner.equals(c.name)
                                && Boolean.TRUE.equals(guarded.get(f.name))) {
                            out.add(new Violation(user.name.replace('/', '.'), m.name, Lines.of(insn),
                                    (f.getOpcode() == Opcodes.PUTFIELD ? "writes " : "reads ") + f.name
                                            + " without the monitor of " + c.name.replace('/', '.')
                                            + ", which its synchronized methods hold for it"));
                        }
                    }
                }
            }
        }
        return out;
    }

    private static boolean hasSynchronizedMethod(ClassNode c) {
        for (MethodNode m : c.methods) {
            if (isSynchronized(m)) {
                return true;
            }
        }
        return false;
    }

    private static boolean isSynchronized(MethodNode m) {
        return (m.access & Opcodes.ACC_SYNCHRONIZED) != 0 && (m.access & Opcodes.ACC_STATIC) == 0;
    }
}
