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
 * into the job's classes (static and special calls to the method the JVM resolves; virtual and
 * interface calls to every override in the pool), the body of every lambda it makes, and the
 * class initialiser of every job class it uses (a class first used by a release is initialised
 * there). In each method reached it reports {@code new}, {@code newarray}, {@code anewarray},
 * {@code multianewarray}, an array's {@code clone()}, an enum's {@code values()} (a copy of its
 * constants), a boxing {@code valueOf}, string concatenation ({@code StringConcatFactory}, or
 * {@code new StringBuilder}), a lambda or method reference ({@code LambdaMetafactory}) and any
 * other {@code invokedynamic}.
 *
 * <p>A call out of the job's classes is looked at where it is made: into another class of the
 * pool (the SCJ layer), the callee is walked the same way and the call is reported when it can
 * reach an allocation that is not an exception thrown on an error path; into the JDK, the call is
 * reported unless the method is one this rule knows not to allocate ({@link #JDK_NO_ALLOCATION}).
 */
public final class AllocationCheck {
    private static final Set<String> BOXES = Set.of("java/lang/Integer", "java/lang/Long", "java/lang/Double",
            "java/lang/Float", "java/lang/Short", "java/lang/Byte", "java/lang/Character", "java/lang/Boolean");

    /**
     * JDK methods a release may call without allocating: {@code owner.name} or {@code owner.*}.
     * A JDK call not listed is reported ("not known"), so the list is where a new call is judged.
     * Their bytecode allocates nothing; what HotSpot's JIT does when a release triggers a C2
     * compilation (interning the class's String literals, once) is the JVM's, not the release's,
     * and is reported by the memory measurement instead (rtsj-compat/README.md).
     */
    static final Set<String> JDK_NO_ALLOCATION = Set.of("java/lang/Math.*", "java/lang/StrictMath.*",
            "java/lang/Double.isNaN", "java/lang/Double.isInfinite", "java/lang/Double.isFinite",
            "java/lang/Double.doubleToRawLongBits", "java/lang/Double.doubleToLongBits",
            "java/lang/Double.longBitsToDouble", "java/lang/Double.compare", "java/lang/Float.isNaN",
            "java/lang/Object.<init>", "java/lang/Enum.<init>", "java/lang/Enum.ordinal", "java/lang/System.nanoTime",
            "java/lang/System.currentTimeMillis", "java/lang/System.arraycopy", "java/lang/Thread.currentThread",
            "java/lang/Integer.numberOfLeadingZeros", "java/lang/Integer.numberOfTrailingZeros",
            "java/lang/Long.numberOfLeadingZeros", "java/lang/Long.numberOfTrailingZeros",
            "java/lang/Long.rotateLeft", "java/lang/Long.rotateRight", "java/lang/Object.notify",
            "java/lang/Object.notifyAll", "java/lang/Object.wait", "java/util/concurrent/locks/LockSupport.*");

    /**
     * Layer methods that allocate only when given no destination object (RTSJ: "if dest is null, a
     * new object is allocated"); the job's code passes its own preallocated one.
     */
    static final Set<String> LAYER_DESTINATION = Set.of(
            "getTime(Ljavax/realtime/AbsoluteTime;)Ljavax/realtime/AbsoluteTime;",
            "getQueryPrecision(Ljavax/realtime/RelativeTime;)Ljavax/realtime/RelativeTime;");

    private final ClassPool pool;
    private final Predicate<String> follow;
    private final Predicate<String> layerClasses;
    /** Job classes initialised before the first release: their initialisers do not run in one. */
    private Set<String> initialisedBefore = Set.of();
    /** Per layer method (a pool class outside the job's): the allocation it can reach, or "" for none. */
    private final java.util.Map<String, String> layer = new java.util.HashMap<>();

    public AllocationCheck(ClassPool pool) {
        this(pool, c -> true);
    }

    /**
     * @param follow which classes (internal names) the walk enters; a memory style that is not
     *               the one checked (the scoped localizer, for the preallocated style) is left out
     */
    public AllocationCheck(ClassPool pool, Predicate<String> follow) {
        this(pool, follow, c -> true);
    }

    /**
     * @param layer which other classes of the pool the job's calls may run (the SCJ layer); an
     *              override in any other class (a test's, a memory style not checked) is not a target
     */
    public AllocationCheck(ClassPool pool, Predicate<String> follow, Predicate<String> layer) {
        this.pool = pool;
        this.follow = follow;
        this.layerClasses = c -> !follow.test(c) && layer.test(c);
    }

    /** Checks every release of the classes {@code isRelease} accepts (internal names). */
    public List<Violation> check(Predicate<String> isRelease) {
        initialisedBefore = initialisedAtStartUp(isRelease);
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
            String what = allocation(insn, pool);
            if (what != null) {
                out.add(new Violation(c.name.replace('/', '.'), m.name, Lines.of(insn),
                        what + " (reached from " + r.root() + ")"));
            }
            String used = classUsed(insn);
            if (used != null && follow.test(used) && pool.get(used) != null && !initialisedBefore.contains(used)) {
                ClassPool.Owned init = pool.resolve(used, "<clinit>", "()V");
                if (init != null && init.owner().name.equals(used) && seen.add(init.key())) {
                    work.add(new Reached(init, r.root() + ", initialising " + used.replace('/', '.')));
                }
            }
            if (insn instanceof InvokeDynamicInsnNode indy && indy.bsmArgs.length > 1
                    && indy.bsmArgs[1] instanceof Handle body) {
                follow(pool.resolve(body.getOwner(), body.getName(), body.getDesc()), r.root(), seen, work);
            }
            if (insn instanceof MethodInsnNode call) {
                List<ClassPool.Owned> targets = targets(call);
                if (what == null && targets.isEmpty() && pool.get(call.owner) == null && !knownJdk(call)) {
                    out.add(new Violation(c.name.replace('/', '.'), m.name, Lines.of(insn),
                            "a JDK call this rule does not know: " + call.owner.replace('/', '.') + "." + call.name
                                    + " (reached from " + r.root() + ")"));
                }
                for (ClassPool.Owned t : targets) {
                    if (follow.test(t.owner().name)) {
                        follow(t, r.root(), seen, work);
                    } else if (layerClasses.test(t.owner().name)
                            && !LAYER_DESTINATION.contains(t.method().name + t.method().desc)) {
                        String inLayer = layerAllocation(t, new HashSet<>());
                        if (!inLayer.isEmpty()) {
                            out.add(new Violation(c.name.replace('/', '.'), m.name, Lines.of(insn),
                                    "calls " + t.owner().name.replace('/', '.') + "." + t.method().name
                                            + ", which allocates: " + inLayer + " (reached from " + r.root() + ")"));
                        }
                    }
                }
            }
        }
    }

    /**
     * The job classes the mission's initialisation uses, so initialises before any release: the
     * classes named (new, static field or call) by every constructor and {@code initialize*}
     * method of the job's classes other than the releases' own methods, and by what they call,
     * and every enum that a job object has a field of (an enum value exists only once its class
     * is initialised).
     */
    private Set<String> initialisedAtStartUp(Predicate<String> isRelease) {
        Set<String> classes = new HashSet<>();
        Set<String> seen = new HashSet<>();
        Deque<ClassPool.Owned> work = new ArrayDeque<>();
        for (ClassNode c : pool.all()) {
            if (!follow.test(c.name)) {
                continue;
            }
            for (MethodNode m : c.methods) {
                if (m.name.equals("<init>") || m.name.startsWith("initialize")) {
                    ClassPool.Owned o = new ClassPool.Owned(c, m);
                    if (seen.add(o.key())) {
                        work.add(o);
                    }
                }
            }
            for (org.objectweb.asm.tree.FieldNode f : c.fields) {
                Type t = Type.getType(f.desc);
                ClassNode type = t.getSort() == Type.OBJECT ? pool.get(t.getInternalName()) : null;
                if (type != null && (type.access & Opcodes.ACC_ENUM) != 0 && (f.access & Opcodes.ACC_STATIC) == 0) {
                    classes.add(type.name);
                }
            }
        }
        while (!work.isEmpty()) {
            ClassPool.Owned o = work.poll();
            for (AbstractInsnNode insn : o.method().instructions) {
                String used = classUsed(insn);
                if (used != null) {
                    classes.add(used);
                }
                if (insn instanceof MethodInsnNode call) {
                    for (ClassPool.Owned t : targets(call)) {
                        if (follow.test(t.owner().name) && seen.add(t.key())) {
                            work.add(t);
                        }
                    }
                }
            }
        }
        return classes;
    }

    private static void follow(ClassPool.Owned t, String root, Set<String> seen, Deque<Reached> work) {
        if (t != null && seen.add(t.key()) && t.method().instructions.size() > 0) {
            work.add(new Reached(t, root));
        }
    }

    private List<ClassPool.Owned> targets(MethodInsnNode call) {
        return call.getOpcode() == Opcodes.INVOKEVIRTUAL || call.getOpcode() == Opcodes.INVOKEINTERFACE
                ? pool.implementations(call.owner, call.name, call.desc)
                : single(pool.resolve(call.owner, call.name, call.desc));
    }

    /**
     * The first allocation a method of the layer (a pool class the job does not own) can reach,
     * as "what at class:line", or "" when it reaches none. Exceptions made to be thrown (an error
     * path) do not count; JDK calls the rule does not know do.
     */
    private String layerAllocation(ClassPool.Owned t, Set<String> visiting) {
        String cached = layer.get(t.key());
        if (cached != null) {
            return cached;
        }
        if (!visiting.add(t.key())) {
            return "";
        }
        String found = "";
        Set<String> thrownTypes = new HashSet<>();
        for (AbstractInsnNode insn : t.method().instructions) {
            String what = allocation(insn, pool);
            if (what != null && thrown(insn)) {
                thrownTypes.add(((TypeInsnNode) insn).desc);
            } else if (what != null) {
                found = what + " at " + t.owner().name.replace('/', '.') + ":" + Lines.of(insn);
            } else if (insn instanceof MethodInsnNode call
                    && !(call.name.equals("<init>") && thrownTypes.contains(call.owner))) {
                List<ClassPool.Owned> targets = targets(call);
                if (targets.isEmpty() && pool.get(call.owner) == null && !knownJdk(call)) {
                    found = "a JDK call not known, " + call.owner.replace('/', '.') + "." + call.name + " at "
                            + t.owner().name.replace('/', '.') + ":" + Lines.of(insn);
                }
                for (ClassPool.Owned u : targets) {
                    String deeper = found.isEmpty() ? layerAllocation(u, visiting) : found;
                    if (!deeper.isEmpty()) {
                        found = deeper;
                    }
                }
            }
            if (!found.isEmpty()) {
                break;
            }
        }
        visiting.remove(t.key());
        layer.put(t.key(), found);
        return found;
    }

    /** True for {@code new X} whose object is thrown: {@code new; dup; ...; invokespecial <init>; athrow}. */
    private static boolean thrown(AbstractInsnNode insn) {
        if (insn.getOpcode() != Opcodes.NEW) {
            return false;
        }
        for (AbstractInsnNode n = insn.getNext(); n != null; n = n.getNext()) {
            if (n instanceof MethodInsnNode call && call.getOpcode() == Opcodes.INVOKESPECIAL
                    && call.owner.equals(((TypeInsnNode) insn).desc) && call.name.equals("<init>")) {
                AbstractInsnNode next = n.getNext();
                while (next != null && next.getOpcode() < 0) {
                    next = next.getNext();
                }
                return next != null && next.getOpcode() == Opcodes.ATHROW;
            }
        }
        return false;
    }

    /** The class whose initialisation the instruction may trigger, or null. */
    private static String classUsed(AbstractInsnNode insn) {
        return switch (insn.getOpcode()) {
            case Opcodes.NEW -> ((TypeInsnNode) insn).desc;
            case Opcodes.GETSTATIC, Opcodes.PUTSTATIC -> ((org.objectweb.asm.tree.FieldInsnNode) insn).owner;
            case Opcodes.INVOKESTATIC -> ((MethodInsnNode) insn).owner;
            default -> null;
        };
    }

    private static boolean knownJdk(MethodInsnNode call) {
        if (call.owner.startsWith("[")) {
            return true; // an array's clone() is an allocation of its own; its other methods are Object's
        }
        return JDK_NO_ALLOCATION.contains(call.owner + "." + call.name) || JDK_NO_ALLOCATION.contains(call.owner + ".*");
    }

    private static List<ClassPool.Owned> single(ClassPool.Owned o) {
        return o == null ? List.of() : List.of(o);
    }

    /** What the instruction allocates, or null. */
    static String allocation(AbstractInsnNode insn, ClassPool pool) {
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
                ClassNode owner = pool.get(call.owner);
                if (call.name.equals("values") && call.desc.startsWith("()[") && owner != null
                        && (owner.access & Opcodes.ACC_ENUM) != 0) {
                    return "enum values() (a new copy of " + Type.getObjectType(call.owner).getClassName()
                            + "'s constants)";
                }
                return null;
            }
            case Opcodes.INVOKEVIRTUAL -> {
                MethodInsnNode call = (MethodInsnNode) insn;
                return call.owner.startsWith("[") && call.name.equals("clone")
                        ? "array clone (" + Type.getType(call.owner).getClassName() + ")" : null;
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
