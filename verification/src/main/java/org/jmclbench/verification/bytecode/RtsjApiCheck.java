package org.jmclbench.verification.bytecode;

import org.objectweb.asm.Handle;
import org.objectweb.asm.Type;
import org.objectweb.asm.tree.AbstractInsnNode;
import org.objectweb.asm.tree.ClassNode;
import org.objectweb.asm.tree.FieldInsnNode;
import org.objectweb.asm.tree.FieldNode;
import org.objectweb.asm.tree.InvokeDynamicInsnNode;
import org.objectweb.asm.tree.LdcInsnNode;
import org.objectweb.asm.tree.MethodInsnNode;
import org.objectweb.asm.tree.MethodNode;
import org.objectweb.asm.tree.MultiANewArrayInsnNode;
import org.objectweb.asm.tree.TryCatchBlockNode;
import org.objectweb.asm.tree.TypeInsnNode;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import java.util.TreeSet;

/**
 * The rtsj engine runs on an RTSJ VM unchanged only if its classes use nothing of rtsj-compat:
 * this rule reads the workload's classes (woven, as Maven builds them, or unwoven, as
 * {@code ant rtsj-engine} does) and reports every reference to a {@code javax.realtime} member
 * outside {@link #RTSJ_1_0_2} (the RTSJ 1.0.2 API the engine may use, each checked against the
 * specification), and every reference into {@code org.jmclbench.rtsjcompat} or
 * {@code javax.safetycritical} except from the shim's rtsj-compat side ({@code CompatShim}, left
 * out of the RTSJ-VM build) and, in woven classes, the weaver's delivery point {@code Atc.poll()}.
 * The scj engine's package (the SCJ variant, also left out) is not read.
 *
 * <p>Usage: {@code RtsjApiCheck (--woven|--unwoven) JAR_OR_FOLDER...}; exit 1 listing the
 * references when there is any, 2 on bad usage.
 */
public final class RtsjApiCheck {
    /** {@code owner.name descriptor} (a class alone: {@code owner}) of RTSJ 1.0.2 the engine uses. */
    static final Set<String> RTSJ_1_0_2 = Set.of(
            "javax/realtime/AbsoluteTime", "javax/realtime/AbsoluteTime.<init> ()V",
            "javax/realtime/AbsoluteTime.set (JI)V",
            "javax/realtime/AbsoluteTime.getMilliseconds ()J", "javax/realtime/AbsoluteTime.getNanoseconds ()I",
            "javax/realtime/HighResolutionTime",
            "javax/realtime/Clock", "javax/realtime/Clock.getRealtimeClock ()Ljavax/realtime/Clock;",
            "javax/realtime/Clock.getTime (Ljavax/realtime/AbsoluteTime;)Ljavax/realtime/AbsoluteTime;",
            "javax/realtime/RealtimeThread",
            "javax/realtime/RealtimeThread.<init> (Ljavax/realtime/SchedulingParameters;Ljavax/realtime/ReleaseParameters;"
                    + "Ljavax/realtime/MemoryParameters;Ljavax/realtime/MemoryArea;"
                    + "Ljavax/realtime/ProcessingGroupParameters;Ljava/lang/Runnable;)V",
            "javax/realtime/RealtimeThread.sleep (Ljavax/realtime/HighResolutionTime;)V",
            // java.lang.Thread's, which RealtimeThread extends (interrupt is RTSJ's own override)
            "javax/realtime/RealtimeThread.setDaemon (Z)V", "javax/realtime/RealtimeThread.start ()V",
            "javax/realtime/RealtimeThread.join (J)V", "javax/realtime/RealtimeThread.isAlive ()Z",
            "javax/realtime/RealtimeThread.interrupt ()V",
            "javax/realtime/PriorityParameters", "javax/realtime/PriorityParameters.<init> (I)V",
            "javax/realtime/PriorityScheduler",
            "javax/realtime/PriorityScheduler.instance ()Ljavax/realtime/PriorityScheduler;",
            "javax/realtime/PriorityScheduler.getMaxPriority ()I",
            "javax/realtime/AsyncEvent", "javax/realtime/AsyncEvent.<init> ()V",
            "javax/realtime/AsyncEvent.addHandler (Ljavax/realtime/AsyncEventHandler;)V",
            "javax/realtime/AsyncEvent.fire ()V",
            "javax/realtime/AsyncEventHandler", "javax/realtime/BoundAsyncEventHandler",
            "javax/realtime/BoundAsyncEventHandler.<init> (Ljavax/realtime/SchedulingParameters;"
                    + "Ljavax/realtime/ReleaseParameters;Ljavax/realtime/MemoryParameters;Ljavax/realtime/MemoryArea;"
                    + "Ljavax/realtime/ProcessingGroupParameters;ZLjava/lang/Runnable;)V",
            "javax/realtime/SchedulingParameters", "javax/realtime/ReleaseParameters",
            "javax/realtime/MemoryParameters", "javax/realtime/MemoryArea", "javax/realtime/ProcessingGroupParameters",
            "javax/realtime/AsynchronouslyInterruptedException",
            "javax/realtime/AsynchronouslyInterruptedException.<init> ()V",
            "javax/realtime/AsynchronouslyInterruptedException.fire ()Z",
            "javax/realtime/AsynchronouslyInterruptedException.doInterruptible (Ljavax/realtime/Interruptible;)Z",
            "javax/realtime/Interruptible");

    /** The only class that may name rtsj-compat: the shim's JVM side. */
    static final String COMPAT_SHIM = "org/jmclbench/workload/shim/CompatShim";
    /** The scj engine's launcher of the SCJ mission: not part of the rtsj engine's build. */
    static final String SCJ_VARIANT = "org/jmclbench/workload/scj/";
    /** The weaver's delivery point, in woven classes only. */
    static final String DELIVERY_POINT = "org/jmclbench/rtsjcompat/Atc.poll ()V";

    private RtsjApiCheck() {
    }

    public static void main(String[] args) throws IOException {
        if (args.length < 2 || !(args[0].equals("--woven") || args[0].equals("--unwoven"))) {
            System.err.println("usage: RtsjApiCheck (--woven|--unwoven) JAR_OR_FOLDER...");
            System.exit(2);
        }
        List<Path> entries = new ArrayList<>();
        for (int i = 1; i < args.length; i++) {
            entries.add(Path.of(args[i]));
        }
        List<String> found = check(ClassPool.of(entries), args[0].equals("--woven"));
        for (String f : found) {
            System.out.println(f);
        }
        System.out.println("rtsj-api: " + (found.isEmpty() ? "the engine uses RTSJ 1.0.2 and the shim only"
                : found.size() + " reference(s) outside RTSJ 1.0.2 and the shim"));
        System.exit(found.isEmpty() ? 0 : 1);
    }

    /** The references of the workload's classes (org/jmclbench/workload/**) that break the rule, as "Class: reference". */
    public static List<String> check(ClassPool pool, boolean woven) {
        Set<String> out = new TreeSet<>();
        int classes = 0;
        for (ClassNode c : pool.all()) {
            if (!c.name.startsWith("org/jmclbench/workload/") || c.name.equals(COMPAT_SHIM)
                    || c.name.startsWith(SCJ_VARIANT)) {
                continue;
            }
            classes++;
            Set<String> refs = new TreeSet<>();
            references(c, refs);
            for (String r : refs) {
                if (!allowed(r, woven)) {
                    out.add(c.name.replace('/', '.') + ": " + r);
                }
            }
        }
        if (classes == 0) {
            out.add("no class of org.jmclbench.workload found: nothing was checked");
        }
        return new ArrayList<>(out);
    }

    static boolean allowed(String ref, boolean woven) {
        if (ref.startsWith("javax/realtime/")) {
            return RTSJ_1_0_2.contains(ref);
        }
        if (ref.startsWith("org/jmclbench/rtsjcompat/")) {
            return woven && ref.equals(DELIVERY_POINT) || woven && ref.equals("org/jmclbench/rtsjcompat/Atc");
        }
        return !ref.startsWith("javax/safetycritical/") && !ref.equals(COMPAT_SHIM) && !ref.startsWith(COMPAT_SHIM + ".");
    }

    /** Every class and member a class names: supertypes, fields, signatures, instructions, handlers. */
    private static void references(ClassNode c, Set<String> refs) {
        if (c.superName != null) {
            refs.add(c.superName);
        }
        refs.addAll(c.interfaces);
        for (FieldNode f : c.fields) {
            type(Type.getType(f.desc), refs);
        }
        for (MethodNode m : c.methods) {
            type(Type.getMethodType(m.desc), refs);
            if (m.exceptions != null) {
                refs.addAll(m.exceptions);
            }
            for (TryCatchBlockNode t : m.tryCatchBlocks) {
                if (t.type != null) {
                    refs.add(t.type);
                }
            }
            for (AbstractInsnNode i : m.instructions) {
                if (i instanceof MethodInsnNode mi) {
                    refs.add(mi.owner);
                    refs.add(mi.owner + "." + mi.name + " " + mi.desc);
                    type(Type.getMethodType(mi.desc), refs);
                } else if (i instanceof FieldInsnNode fi) {
                    refs.add(fi.owner);
                    refs.add(fi.owner + "." + fi.name + " " + fi.desc);
                    type(Type.getType(fi.desc), refs);
                } else if (i instanceof TypeInsnNode ti) {
                    type(Type.getObjectType(ti.desc), refs);
                } else if (i instanceof MultiANewArrayInsnNode ma) {
                    type(Type.getType(ma.desc), refs);
                } else if (i instanceof LdcInsnNode l && l.cst instanceof Type t) {
                    type(t, refs);
                } else if (i instanceof InvokeDynamicInsnNode indy) {
                    type(Type.getMethodType(indy.desc), refs);
                    for (Object a : indy.bsmArgs) {
                        if (a instanceof Handle h) {
                            refs.add(h.getOwner());
                            refs.add(h.getOwner() + "." + h.getName() + " " + h.getDesc());
                        } else if (a instanceof Type t) {
                            type(t, refs);
                        }
                    }
                }
            }
        }
    }

    private static void type(Type t, Set<String> refs) {
        switch (t.getSort()) {
            case Type.ARRAY -> type(t.getElementType(), refs);
            case Type.OBJECT -> refs.add(t.getInternalName());
            case Type.METHOD -> {
                type(t.getReturnType(), refs);
                for (Type a : t.getArgumentTypes()) {
                    type(a, refs);
                }
            }
            default -> { }
        }
    }
}
