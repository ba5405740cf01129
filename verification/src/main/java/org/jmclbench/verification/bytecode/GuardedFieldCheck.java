package org.jmclbench.verification.bytecode;

import org.objectweb.asm.Opcodes;
import org.objectweb.asm.tree.AbstractInsnNode;
import org.objectweb.asm.tree.ClassNode;
import org.objectweb.asm.tree.FieldInsnNode;
import org.objectweb.asm.tree.FieldNode;
import org.objectweb.asm.tree.MethodInsnNode;
import org.objectweb.asm.tree.MethodNode;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
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
 *
 * <p>The monitor also guards the objects it owns: a final field whose object a synchronized method
 * calls (the robot's localizer, whose particles the jobs change) is called only under it; a method
 * of the class that reads it and calls its type outside the monitor is reported (a getter that
 * only hands the object out is not a call). A private method called only where the monitor is held
 * holds it too (the robot's {@code commit}).
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
            Set<MethodNode> held = monitorHeld(c);
            // final fields whose object a method under the monitor calls: the monitor owns that object
            Map<String, String> owned = new HashMap<>();
            for (MethodNode m : held) {
                for (AbstractInsnNode insn : m.instructions) {
                    if (insn instanceof FieldInsnNode f && f.owner.equals(c.name) && guarded.containsKey(f.name)) {
                        guarded.put(f.name, true);
                    }
                    if (insn instanceof FieldInsnNode f && f.getOpcode() == Opcodes.GETFIELD && f.owner.equals(c.name)
                            && isFinalReference(c, f.name) && calls(m, typeOf(f.desc))) {
                        owned.put(f.name, typeOf(f.desc));
                    }
                }
            }
            for (ClassNode user : pool.all()) {
                if (!follow.test(user.name)) {
                    continue;
                }
                for (MethodNode m : user.methods) {
                    if (user == c && (held.contains(m) || m.name.equals("<init>"))) {
                        continue;
                    }
                    for (AbstractInsnNode insn : m.instructions) {
                        if (!(insn instanceof FieldInsnNode f) || !f.owner.equals(c.name)) {
                            continue;
                        }
                        if (Boolean.TRUE.equals(guarded.get(f.name))) {
                            out.add(new Violation(user.name.replace('/', '.'), m.name, Lines.of(insn),
                                    (f.getOpcode() == Opcodes.PUTFIELD ? "writes " : "reads ") + f.name
                                            + " without the monitor of " + c.name.replace('/', '.')
                                            + ", which its synchronized methods hold for it"));
                        } else if (f.getOpcode() == Opcodes.GETFIELD && owned.containsKey(f.name) && calls(m, owned.get(f.name))) {
                            out.add(new Violation(user.name.replace('/', '.'), m.name, Lines.of(insn),
                                    "calls " + f.name + " without the monitor of " + c.name.replace('/', '.')
                                            + ", whose synchronized methods own that object"));
                        }
                    }
                }
            }
        }
        return out;
    }

    /**
     * The methods of {@code c} that run holding its monitor: the synchronized ones, and the private
     * ones called only from those (to a fixed point).
     */
    private static Set<MethodNode> monitorHeld(ClassNode c) {
        Set<MethodNode> held = new HashSet<>();
        for (MethodNode m : c.methods) {
            if (isSynchronized(m)) {
                held.add(m);
            }
        }
        boolean grew = true;
        while (grew) {
            grew = false;
            for (MethodNode m : c.methods) {
                if (held.contains(m) || (m.access & Opcodes.ACC_PRIVATE) == 0 || (m.access & Opcodes.ACC_STATIC) != 0) {
                    continue;
                }
                boolean called = false;
                boolean onlyHeld = true;
                for (MethodNode caller : c.methods) {
                    for (AbstractInsnNode insn : caller.instructions) {
                        if (insn instanceof MethodInsnNode call && call.owner.equals(c.name) && call.name.equals(m.name)
                                && call.desc.equals(m.desc)) {
                            called = true;
                            onlyHeld &= held.contains(caller);
                        }
                    }
                }
                if (called && onlyHeld) {
                    held.add(m);
                    grew = true;
                }
            }
        }
        return held;
    }

    private static boolean isFinalReference(ClassNode c, String field) {
        for (FieldNode f : c.fields) {
            if (f.name.equals(field)) {
                return (f.access & (Opcodes.ACC_FINAL | Opcodes.ACC_STATIC)) == Opcodes.ACC_FINAL && f.desc.startsWith("L");
            }
        }
        return false;
    }

    /** The internal name of a field's object type ({@code Lpkg/Type;}), or the descriptor itself. */
    private static String typeOf(String desc) {
        return desc.startsWith("L") ? desc.substring(1, desc.length() - 1) : desc;
    }

    /** Whether {@code m} calls an instance method declared by {@code type}. */
    private static boolean calls(MethodNode m, String type) {
        for (AbstractInsnNode insn : m.instructions) {
            if (insn instanceof MethodInsnNode call && call.owner.equals(type) && call.getOpcode() != Opcodes.INVOKESTATIC
                    && call.getOpcode() != Opcodes.INVOKESPECIAL) {
                return true;
            }
        }
        return false;
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
