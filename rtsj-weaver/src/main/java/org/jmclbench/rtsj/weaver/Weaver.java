package org.jmclbench.rtsj.weaver;

import java.io.IOException;
import java.io.PrintStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.ArrayList;
import java.util.BitSet;
import java.util.List;
import java.util.stream.Collectors;
import java.util.stream.Stream;
import org.objectweb.asm.ClassReader;
import org.objectweb.asm.ClassWriter;
import org.objectweb.asm.Opcodes;
import org.objectweb.asm.tree.AbstractInsnNode;
import org.objectweb.asm.tree.AnnotationNode;
import org.objectweb.asm.tree.ClassNode;
import org.objectweb.asm.tree.InvokeDynamicInsnNode;
import org.objectweb.asm.tree.JumpInsnNode;
import org.objectweb.asm.tree.LabelNode;
import org.objectweb.asm.tree.LookupSwitchInsnNode;
import org.objectweb.asm.tree.MethodInsnNode;
import org.objectweb.asm.tree.MethodNode;
import org.objectweb.asm.tree.TableSwitchInsnNode;

/**
 * Weaves RTSJ delivery points into AI-enabled methods: a call to
 * {@code org.jmclbench.rtsjcompat.Atc.poll()} at the method's entry, before every backward branch,
 * after every call and where a synchronized block or a finally ends, wherever the instruction is
 * not in a monitor region or a {@code finally} ({@link MethodRegions}). AI-enabled means declaring
 * {@code AsynchronouslyInterruptedException} itself (not a subclass) in the throws clause, as RTSJ
 * defines it; nothing else is touched, so every other method keeps RTSJ's deferral by having no
 * delivery point at all.
 *
 * <p>The woven class carries an invisible marker annotation, so weaving twice (an incremental
 * build) changes nothing. {@code main(dirs...)} rewrites the classes under each directory in
 * place: exit 0 with a one-line summary, 2 on a bad argument or a file that is not a class file,
 * 1 when a method cannot be woven.
 */
public final class Weaver {
    /** RTSJ's AIE, in internal form. */
    public static final String AIE = "javax/realtime/AsynchronouslyInterruptedException";
    /** The delivery point: owner, name and descriptor. */
    public static final String POLL_OWNER = "org/jmclbench/rtsjcompat/Atc";
    public static final String POLL_NAME = "poll";
    public static final String POLL_DESC = "()V";
    /** The marker of a woven class. */
    public static final String MARKER = "Lorg/jmclbench/rtsj/weaver/DeliveryPointsWoven;";

    /** The result of weaving one class. */
    public static final class Result {
        /** The new class file (the input when nothing was woven). */
        public final byte[] bytes;
        /** AI-enabled methods found, and delivery points inserted. */
        public final int aiMethods;
        public final int deliveryPoints;
        /**
         * The class was woven by an earlier build (and left as it is): its AI-enabled methods and
         * the delivery points already in them, counted so that a rebuild does not report "0".
         */
        public final int aiMethodsBefore;
        public final int deliveryPointsBefore;

        Result(byte[] bytes, int aiMethods, int deliveryPoints) {
            this(bytes, aiMethods, deliveryPoints, 0, 0);
        }

        private Result(byte[] bytes, int aiMethods, int deliveryPoints, int aiMethodsBefore, int deliveryPointsBefore) {
            this.bytes = bytes;
            this.aiMethods = aiMethods;
            this.deliveryPoints = deliveryPoints;
            this.aiMethodsBefore = aiMethodsBefore;
            this.deliveryPointsBefore = deliveryPointsBefore;
        }
    }

    /** A file named {@code .class} that ASM cannot read: bad input, not a method the weaver refuses. */
    public static final class UnreadableClassException extends RuntimeException {
        private static final long serialVersionUID = 1L;

        UnreadableClassException(RuntimeException cause) {
            super("not a class file this weaver can read (" + cause + ")", cause);
        }
    }

    private final boolean deferFinally;

    /** A weaver with RTSJ's rules. */
    public Weaver() {
        this(true);
    }

    /**
     * {@code deferFinally} false puts delivery points into finally code too: a seeded bug for the
     * tests that must catch a delivery inside a finally. Never used by the build.
     */
    Weaver(boolean deferFinally) {
        this.deferFinally = deferFinally;
    }

    /** Weaves one class file. */
    public Result weave(byte[] classFile) {
        ClassNode c = new ClassNode();
        try {
            new ClassReader(classFile).accept(c, 0);
        } catch (RuntimeException e) {
            // ASM reports a truncated or foreign file as an index out of bounds, a newer class-file
            // version as an IllegalArgumentException: either way, nothing to weave
            throw new UnreadableClassException(e);
        }
        if (woven(c)) {
            return wovenBefore(classFile, c);
        }
        int ai = 0;
        int points = 0;
        for (MethodNode m : c.methods) {
            if (weavable(m)) {
                ai++;
                points += weave(m, c.name.replace('/', '.') + "." + m.name + m.desc);
            }
        }
        if (ai == 0) {
            return new Result(classFile, 0, 0);
        }
        if (c.invisibleAnnotations == null) {
            c.invisibleAnnotations = new ArrayList<>();
        }
        c.invisibleAnnotations.add(new AnnotationNode(MARKER));
        ClassWriter w = new ClassWriter(ClassWriter.COMPUTE_MAXS);
        c.accept(w);
        return new Result(w.toByteArray(), ai, points);
    }

    private static Result wovenBefore(byte[] classFile, ClassNode c) {
        int ai = 0;
        int points = 0;
        for (MethodNode m : c.methods) {
            if (weavable(m)) {
                ai++;
                for (AbstractInsnNode n : m.instructions.toArray()) {
                    points += isPoll(n) ? 1 : 0;
                }
            }
        }
        return new Result(classFile, 0, 0, ai, points);
    }

    /** Whether {@code m} declares the AIE itself in its throws clause. */
    public static boolean aiEnabled(MethodNode m) {
        return m.exceptions != null && m.exceptions.contains(AIE);
    }

    /**
     * An AI-enabled method with code: what the weaver weaves, and what a rebuild counts as woven
     * (an abstract or native method declaring the AIE has no code to hold a delivery point).
     */
    private static boolean weavable(MethodNode m) {
        return aiEnabled(m) && m.instructions.size() > 0;
    }

    private static boolean woven(ClassNode c) {
        if (c.invisibleAnnotations != null) {
            for (AnnotationNode a : c.invisibleAnnotations) {
                if (MARKER.equals(a.desc)) {
                    return true;
                }
            }
        }
        return false;
    }

    private int weave(MethodNode m, String where) {
        MethodRegions r = new MethodRegions(m, where);
        AbstractInsnNode[] insns = r.instructions();
        int points = 0;
        boolean entryDone = false;
        BitSet exits = r.deferralExits(i -> deliverable(r, i));
        for (int i = 0; i < insns.length; i++) {
            AbstractInsnNode n = insns[i];
            if (n.getOpcode() < 0) {
                continue; // labels, line numbers, frames
            }
            boolean entry = !entryDone;
            entryDone = true;
            // one delivery point before the instruction, whichever of the rules asks for it
            if (deliverable(r, i) && (entry || backwardBranch(r, n, i) || exits.get(i))) {
                m.instructions.insertBefore(n, poll());
                points++;
            }
            if (isCall(n) && deliverable(r, i)) {
                m.instructions.insert(n, poll());
                points++;
            }
        }
        return points;
    }

    private boolean deliverable(MethodRegions r, int i) {
        return deferFinally ? r.deliverable(i) : r.deliverableIgnoringFinally(i);
    }

    private static boolean isPoll(AbstractInsnNode n) {
        return n instanceof MethodInsnNode && POLL_OWNER.equals(((MethodInsnNode) n).owner)
                && POLL_NAME.equals(((MethodInsnNode) n).name);
    }

    private static boolean isCall(AbstractInsnNode n) {
        return n instanceof MethodInsnNode ? !isPoll(n) : n instanceof InvokeDynamicInsnNode;
    }

    private static boolean backwardBranch(MethodRegions r, AbstractInsnNode n, int i) {
        if (n instanceof JumpInsnNode) {
            return r.indexOf(((JumpInsnNode) n).label) <= i;
        }
        List<LabelNode> targets = new ArrayList<>();
        if (n instanceof TableSwitchInsnNode) {
            targets.add(((TableSwitchInsnNode) n).dflt);
            targets.addAll(((TableSwitchInsnNode) n).labels);
        } else if (n instanceof LookupSwitchInsnNode) {
            targets.add(((LookupSwitchInsnNode) n).dflt);
            targets.addAll(((LookupSwitchInsnNode) n).labels);
        }
        for (LabelNode l : targets) {
            if (r.indexOf(l) <= i) {
                return true;
            }
        }
        return false;
    }

    private static MethodInsnNode poll() {
        return new MethodInsnNode(Opcodes.INVOKESTATIC, POLL_OWNER, POLL_NAME, POLL_DESC, false);
    }

    /** What a directory holds after weaving, and how much of it an earlier build wove. */
    static String summary(int ai, int points, int aiBefore, int pointsBefore) {
        String all = (ai + aiBefore) + " AI-enabled methods, " + (points + pointsBefore) + " delivery points";
        if (aiBefore == 0) {
            return all;
        }
        return all + (ai == 0 ? " (woven by an earlier build)" : " (" + aiBefore + " of the methods woven by an earlier build)");
    }

    /** Weaves the classes under each directory in place. */
    public static void main(String[] args) {
        System.exit(run(args, System.out, System.err));
    }

    static int run(String[] args, PrintStream out, PrintStream err) {
        if (args.length == 0) {
            err.println("rtsj-weaver: usage: Weaver CLASS_DIR...");
            return 2;
        }
        Weaver w = new Weaver();
        for (String a : args) {
            Path dir = Paths.get(a);
            if (!Files.isDirectory(dir)) {
                err.println("rtsj-weaver: not a directory: " + a);
                return 2;
            }
            int ai = 0;
            int points = 0;
            int aiBefore = 0;
            int pointsBefore = 0;
            try {
                List<Path> files;
                try (Stream<Path> s = Files.walk(dir)) {
                    files = s.filter(p -> p.toString().endsWith(".class")).sorted().collect(Collectors.toList());
                }
                for (Path f : files) {
                    byte[] in = Files.readAllBytes(f);
                    Result r;
                    try {
                        r = w.weave(in);
                    } catch (UnreadableClassException e) {
                        err.println("rtsj-weaver: " + f + ": " + e.getMessage());
                        return 2;
                    }
                    if (r.bytes != in) {
                        Files.write(f, r.bytes);
                    }
                    ai += r.aiMethods;
                    points += r.deliveryPoints;
                    aiBefore += r.aiMethodsBefore;
                    pointsBefore += r.deliveryPointsBefore;
                }
            } catch (WeaveException e) {
                err.println("rtsj-weaver: " + e.getMessage());
                return 1;
            } catch (IOException e) {
                err.println("rtsj-weaver: " + dir + ": " + e.getMessage());
                return 1;
            }
            out.println("rtsj-weaver: " + dir + ": " + summary(ai, points, aiBefore, pointsBefore));
        }
        return 0;
    }
}
