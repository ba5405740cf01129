package org.jmclbench.verification.bytecode;

import org.objectweb.asm.Handle;
import org.objectweb.asm.Opcodes;
import org.objectweb.asm.Type;
import org.objectweb.asm.tree.AbstractInsnNode;
import org.objectweb.asm.tree.ClassNode;
import org.objectweb.asm.tree.InvokeDynamicInsnNode;
import org.objectweb.asm.tree.MethodInsnNode;
import org.objectweb.asm.tree.MethodNode;
import org.objectweb.asm.tree.MultiANewArrayInsnNode;
import org.objectweb.asm.tree.TypeInsnNode;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import java.util.function.Predicate;

/**
 * Static P6: nothing reachable from a preallocated release's {@code handleAsyncEvent} allocates.
 *
 * <p>The walk starts at {@code handleAsyncEvent()V} of each release class and follows every call
 * into the project's classes (static and special calls to the method the JVM resolves; virtual
 * and interface calls to every override in the pool). In each method reached it reports
 * {@code new}, {@code newarray}, {@code anewarray}, {@code multianewarray}, a boxing
 * {@code valueOf}, string concatenation ({@code StringConcatFactory}, or {@code new
 * StringBuilder}), a lambda or method reference ({@code LambdaMetafactory}) and any other
 * {@code invokedynamic}. Calls into the JDK are not followed (the SCJ subset the job code may
 * use: Math and the like). Class initialisers are not reached by calls and are not looked at.
 */
public final class AllocationCheck {
    private static final Set<String> BOXES = Set.of("java/lang/Integer", "java/lang/Long", "java/lang/Double",
            "java/lang/Float", "java/lang/Short", "java/lang/Byte", "java/lang/Character", "java/lang/Boolean");

    private final ClassPool pool;
    private final Predicate<String> follow;

    public AllocationCheck(ClassPool pool) {
        this(pool, c -> true);
    }

    /**
     * @param follow which classes (internal names) the walk enters; a memory style that is not
     *               the one checked (the scoped localizer, for the preallocated style) is left out
     */
    public AllocationCheck(ClassPool pool, Predicate<String> follow) {
        this.pool = pool;
        this.follow = follow;
    }

    /** Checks every release of the classes {@code isRelease} accepts (internal names). */
    public List<Violation> check(Predicate<String> isRelease) {
        List<Violation> out = new ArrayList<>();
        Set<String> seen = new HashSet<>();
        Deque<Reached> work = new ArrayDeque<>();
        for (ClassNode c : pool.all()) {
            if (isRelease.test(c.name)) {
                ClassPool.Owned m = pool.resolve(c.name, "handleAsyncEvent", "()V");
                if (m != null && seen.add(m.key())) {
                    work.add(new Reached(m, c.name.replace('/', '.') + ".handleAsyncEvent"));
                }
            }
        }
        while (!work.isEmpty()) {
            Reached r = work.poll();
            scan(r, out, seen, work);
        }
        return out;
    }

    private void scan(Reached r, List<Violation> out, Set<String> seen, Deque<Reached> work) {
        ClassNode c = r.m().owner();
        MethodNode m = r.m().method();
        for (AbstractInsnNode insn : m.instructions) {
            String what = allocation(insn);
            if (what != null) {
                out.add(new Violation(c.name.replace('/', '.'), m.name, Lines.of(insn),
                        what + " (reached from " + r.root() + ")"));
            }
            if (insn instanceof MethodInsnNode call) {
                List<ClassPool.Owned> targets = call.getOpcode() == Opcodes.INVOKEVIRTUAL
                        || call.getOpcode() == Opcodes.INVOKEINTERFACE
                        ? pool.implementations(call.owner, call.name, call.desc)
                        : single(pool.resolve(call.owner, call.name, call.desc));
                for (ClassPool.Owned t : targets) {
                    if (follow.test(t.owner().name) && seen.add(t.key()) && t.method().instructions.size() > 0) {
                        work.add(new Reached(t, r.root()));
                    }
                }
            }
        }
    }

    private static List<ClassPool.Owned> single(ClassPool.Owned o) {
        return o == null ? List.of() : List.of(o);
    }

    /** What the instruction allocates, or null. */
    static String allocation(AbstractInsnNode insn) {
        switch (insn.getOpcode()) {
            case Opcodes.NEW -> {
                String t = ((TypeInsnNode) insn).desc;
                return t.equals("java/lang/StringBuilder") || t.equals("java/lang/StringBuffer")
                        ? "string building (new " + Type.getObjectType(t).getClassName() + ")"
                        : "new " + Type.getObjectType(t).getClassName();
            }
            case Opcodes.NEWARRAY -> {
                return "newarray";
            }
            case Opcodes.ANEWARRAY -> {
                return "anewarray " + Type.getObjectType(((TypeInsnNode) insn).desc).getClassName();
            }
            case Opcodes.MULTIANEWARRAY -> {
                return "multianewarray " + Type.getType(((MultiANewArrayInsnNode) insn).desc).getClassName();
            }
            case Opcodes.INVOKESTATIC -> {
                MethodInsnNode call = (MethodInsnNode) insn;
                if (call.name.equals("valueOf") && BOXES.contains(call.owner)) {
                    return "boxing (" + Type.getObjectType(call.owner).getClassName() + ".valueOf)";
                }
                return null;
            }
            case Opcodes.INVOKEDYNAMIC -> {
                Handle bsm = ((InvokeDynamicInsnNode) insn).bsm;
                if (bsm.getOwner().equals("java/lang/invoke/StringConcatFactory")) {
                    return "string concatenation (invokedynamic " + bsm.getName() + ")";
                }
                if (bsm.getOwner().equals("java/lang/invoke/LambdaMetafactory")) {
                    return "lambda or method reference (invokedynamic LambdaMetafactory)";
                }
                return "invokedynamic " + bsm.getOwner() + "." + bsm.getName();
            }
            default -> {
                return null;
            }
        }
    }

    private record Reached(ClassPool.Owned m, String root) {
    }
}
