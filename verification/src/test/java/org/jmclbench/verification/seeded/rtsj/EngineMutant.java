package org.jmclbench.verification.seeded.rtsj;

import org.objectweb.asm.ClassReader;
import org.objectweb.asm.ClassWriter;
import org.objectweb.asm.Opcodes;
import org.objectweb.asm.tree.AbstractInsnNode;
import org.objectweb.asm.tree.ClassNode;
import org.objectweb.asm.tree.FieldInsnNode;
import org.objectweb.asm.tree.InsnList;
import org.objectweb.asm.tree.InsnNode;
import org.objectweb.asm.tree.MethodInsnNode;
import org.objectweb.asm.tree.MethodNode;
import org.objectweb.asm.tree.TryCatchBlockNode;
import org.objectweb.asm.tree.VarInsnNode;

import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.function.Consumer;

/**
 * A seeded bug that is an edit of one shipped class, the rtsj engine's, the RTSJ layer's, the
 * policies' rule or the SCJ mission's: the
 * class as the build made it (woven) is read from the class path, one method is edited with ASM
 * and the result is written to a folder of its own, which the check puts first on JPF's class
 * path. So the program checked is the shipped one with exactly that slip in it, and nothing of
 * the engine is copied into the test sources.
 */
public enum EngineMutant {
    /** lockAndRun's finally releases the robot's lock on the normal path only: an AIE leaks it. */
    UNLOCK_NOT_IN_FINALLY(EngineMutant.TASK, "lockAndRun", m -> {
        for (TryCatchBlockNode t : m.tryCatchBlocks) {
            if (t.type == null) {
                for (AbstractInsnNode i = t.handler; i != null && i.getOpcode() != Opcodes.ATHROW; i = i.getNext()) {
                    if (isCall(i, "java/util/concurrent/locks/ReentrantLock", "unlock")) {
                        i = replace(m, i, new InsnNode(Opcodes.POP));
                    }
                }
            }
        }
    }),
    /** doInterruptible forgets to clear its AIE: still pending, it is delivered in the handler's next job. */
    CLEAR_FORGOTTEN(EngineMutant.AIE, "doInterruptible", m -> {
        for (AbstractInsnNode i : m.instructions.toArray()) {
            // s.clear(this), in every copy javac made of the finally block (s.clear(GENERIC) stays)
            if (isCall(i, "org/jmclbench/rtsjcompat/AtcState", "clear") && i.getPrevious() instanceof VarInsnNode v
                    && v.var == 0) {
                replace(m, i, new InsnNode(Opcodes.POP), new InsnNode(Opcodes.POP), new InsnNode(Opcodes.ICONST_0));
            }
        }
    }),
    /** doInterruptible no longer catches its AIE: it escapes to the handler. */
    AIE_ESCAPES(EngineMutant.AIE, "doInterruptible", m -> {
        for (TryCatchBlockNode t : m.tryCatchBlocks) {
            if (EngineMutant.AIE.equals(t.type)) {
                t.type = "java/lang/ThreadDeath";
            }
        }
    }),
    /** The thesis design's job polls with delivery points inside the robot's monitor. */
    POLL_IN_MONITOR(EngineMutant.TASK, "run", m -> {
        if (!m.desc.equals("(Ljavax/realtime/AsynchronouslyInterruptedException;)V")) {
            return;
        }
        for (AbstractInsnNode i : m.instructions.toArray()) {
            if (i instanceof FieldInsnNode f && f.getOpcode() == Opcodes.GETSTATIC && f.name.equals("NEVER")) {
                replace(m, i, new FieldInsnNode(Opcodes.GETSTATIC, "org/jmclbench/workload/rtsj/DeliveryPoints",
                        "INSTANCE", "Lorg/jmclbench/workload/rtsj/DeliveryPoints;"));
            }
        }
    }),
    /** The weaver's slip: a delivery point at the entry of runJob, the robot work, which is not AI-enabled. */
    POLL_IN_NON_AI(EngineMutant.TASK, "runJob", m -> m.instructions.insert(
            new MethodInsnNode(Opcodes.INVOKESTATIC, "org/jmclbench/rtsjcompat/Atc", "poll", "()V", false))),
    /** ended() no longer notifies: the dispatcher waits for every event's end forever. */
    LOST_NOTIFY(EngineMutant.REPLAY, "ended", m -> {
        for (AbstractInsnNode i : m.instructions.toArray()) {
            if (isCall(i, "java/lang/Object", "notifyAll")) {
                replace(m, i, new InsnNode(Opcodes.POP));
            }
        }
    }),
    /** A release ends its event twice. */
    ENDS_TWICE(EngineMutant.TASK, "run", m -> {
        if (!m.desc.equals("()V")) {
            return;
        }
        for (AbstractInsnNode i : m.instructions.toArray()) {
            if (i instanceof MethodInsnNode c && c.name.equals("finish")) {
                InsnList again = new InsnList();
                again.add(new VarInsnNode(Opcodes.ALOAD, 0));
                again.add(new MethodInsnNode(c.getOpcode(), c.owner, c.name, c.desc, c.itf));
                m.instructions.insert(i, again);
            }
        }
    }),
    /**
     * The latest release is no longer published: every job thinks it was superseded. Terminate's
     * rule (the second constant's body of OverrunPolicy), which the dispatcher's admit runs.
     */
    LATEST_LOST(EngineMutant.TERMINATE_RULE, null, m -> {
        if (m.name.equals("<init>")) {
            return;
        }
        for (AbstractInsnNode i : m.instructions.toArray()) {
            if (i instanceof FieldInsnNode f && f.getOpcode() == Opcodes.PUTFIELD && f.name.equals("latest")) {
                replace(m, i, new InsnNode(Opcodes.POP), new InsnNode(Opcodes.POP));
            }
        }
    }),
    /** The mission's robot: predict no longer takes the robot's monitor (update still does). */
    ROBOT_PREDICT_UNSYNCHRONISED(EngineMutant.ROBOT, "predict", m -> m.access &= ~Opcodes.ACC_SYNCHRONIZED),
    /** The mission's job runner no longer holds the robot's monitor around the job (the robot's methods still may). */
    RUNNER_ROBOT_UNLOCKED(EngineMutant.RUNNER, "run", m -> {
        for (AbstractInsnNode i : m.instructions.toArray()) {
            if (i.getOpcode() == Opcodes.MONITORENTER || i.getOpcode() == Opcodes.MONITOREXIT) {
                replace(m, i, new InsnNode(Opcodes.POP));
            }
        }
    });

    static final String ROBOT = "org/jmclbench/scj/Robot";
    static final String RUNNER = "org/jmclbench/scj/JobRunner";
    static final String REPLAY = "org/jmclbench/workload/rtsj/RtsjReplay";
    static final String TERMINATE_RULE = "org/jmclbench/core/policy/OverrunPolicy$2";
    static final String TASK = REPLAY + "$Task";
    static final String AIE = "javax/realtime/AsynchronouslyInterruptedException";

    private final String owner;
    private final String method;
    private final Consumer<MethodNode> edit;

    EngineMutant(String owner, String method, Consumer<MethodNode> edit) {
        this.owner = owner;
        this.method = method;
        this.edit = edit;
    }

    /** The class edited, as {@code Class.method} names it ({@code a.b.C$D}). */
    public String className() {
        return owner.replace('/', '.');
    }

    /**
     * Writes the edited class under {@code root}/{@code id}/ and returns that folder. Fails when
     * the edit changed nothing (the shipped code no longer has what the bug edits).
     */
    public Path writeUnder(Path root, String id) {
        try (InputStream in = EngineMutant.class.getClassLoader().getResourceAsStream(owner + ".class")) {
            if (in == null) {
                throw new IllegalStateException(owner + " is not on the class path");
            }
            byte[] shipped = in.readAllBytes();
            ClassNode c = new ClassNode();
            new ClassReader(shipped).accept(c, 0);
            for (MethodNode m : c.methods) {
                if (method == null || m.name.equals(method)) {
                    edit.accept(m);
                }
            }
            ClassWriter w = new ClassWriter(ClassWriter.COMPUTE_MAXS);
            c.accept(w);
            byte[] edited = w.toByteArray();
            if (java.util.Arrays.equals(edited, new ClassWriterCopy(shipped).bytes())) {
                throw new IllegalStateException(name() + ": nothing to edit in " + owner + "." + method);
            }
            Path dir = root.resolve(id);
            Path file = dir.resolve(owner + ".class");
            Files.createDirectories(file.getParent());
            Files.write(file, edited);
            return dir;
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    private static boolean isCall(AbstractInsnNode i, String owner, String name) {
        return i instanceof MethodInsnNode c && c.owner.equals(owner) && c.name.equals(name);
    }

    /** Replaces {@code i} with {@code with}; returns the last instruction put in. */
    private static AbstractInsnNode replace(MethodNode m, AbstractInsnNode i, AbstractInsnNode... with) {
        InsnList l = new InsnList();
        for (AbstractInsnNode w : with) {
            l.add(w);
        }
        AbstractInsnNode last = with[with.length - 1];
        m.instructions.insert(i, l);
        m.instructions.remove(i);
        return last;
    }

    /** The shipped class passed through ASM unchanged, to compare an edit with. */
    private record ClassWriterCopy(byte[] shipped) {
        byte[] bytes() {
            ClassNode c = new ClassNode();
            new ClassReader(shipped).accept(c, 0);
            ClassWriter w = new ClassWriter(ClassWriter.COMPUTE_MAXS);
            c.accept(w);
            return w.toByteArray();
        }
    }
}
