package org.jmclbench.verification;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.jmclbench.verification.bytecode.ClassPool;
import org.jmclbench.verification.bytecode.RtsjApiCheck;
import org.junit.jupiter.api.Test;
import org.objectweb.asm.ClassWriter;
import org.objectweb.asm.MethodVisitor;
import org.objectweb.asm.Opcodes;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

/**
 * The rtsj engine's classes as Maven builds them (woven) use RTSJ 1.0.2 and the shim only, and the
 * rule can fail: the same classes fail as unwoven (they call the weaver's delivery point), and a
 * class using an rtsj-compat-only member of javax.realtime or rtsj-compat itself is reported.
 * (The unwoven build, {@code ant rtsj-engine}, is checked by scripts/test-all.sh with the same rule.)
 */
class RtsjApiCheckTest {
    private static Path workloadClasses() throws Exception {
        return Path.of(Class.forName("org.jmclbench.workload.rtsj.RtsjReplay").getProtectionDomain().getCodeSource()
                .getLocation().toURI());
    }

    @Test
    void theWovenEngineUsesRtsj102AndTheShimOnly() throws Exception {
        assertEquals(List.of(), RtsjApiCheck.check(ClassPool.of(List.of(workloadClasses())), true));
    }

    @Test
    void theWovenEngineFailsAsUnwovenForItsDeliveryPoints() throws Exception {
        List<String> found = RtsjApiCheck.check(ClassPool.of(List.of(workloadClasses())), false);
        assertTrue(found.stream().anyMatch(f -> f.contains("RtsjReplay$Task: org/jmclbench/rtsjcompat/Atc.poll ()V")),
                found.toString());
    }

    @Test
    void anRtsjCompatOnlyMemberOrTheLayerItselfIsReported() throws Exception {
        ClassWriter w = new ClassWriter(ClassWriter.COMPUTE_MAXS | ClassWriter.COMPUTE_FRAMES);
        w.visit(Opcodes.V1_8, Opcodes.ACC_PUBLIC, "org/jmclbench/workload/rtsj/Seeded", null, "java/lang/Object", null);
        MethodVisitor m = w.visitMethod(Opcodes.ACC_STATIC, "use", "(Ljavax/realtime/HighResolutionTime;)J", null, null);
        m.visitCode();
        m.visitMethodInsn(Opcodes.INVOKESTATIC, "org/jmclbench/rtsjcompat/RtsjRuntime", "reset", "()V", false);
        m.visitVarInsn(Opcodes.ALOAD, 0);
        m.visitMethodInsn(Opcodes.INVOKEVIRTUAL, "javax/realtime/HighResolutionTime", "toNanos", "()J", false);
        m.visitInsn(Opcodes.LRETURN);
        m.visitMaxs(0, 0);
        m.visitEnd();
        Path dir = Files.createTempDirectory("rtsj-api");
        Path f = dir.resolve("org/jmclbench/workload/rtsj/Seeded.class");
        Files.createDirectories(f.getParent());
        Files.write(f, w.toByteArray());
        assertEquals(List.of("org.jmclbench.workload.rtsj.Seeded: javax/realtime/HighResolutionTime.toNanos ()J",
                        "org.jmclbench.workload.rtsj.Seeded: org/jmclbench/rtsjcompat/RtsjRuntime",
                        "org.jmclbench.workload.rtsj.Seeded: org/jmclbench/rtsjcompat/RtsjRuntime.reset ()V"),
                RtsjApiCheck.check(ClassPool.of(List.of(dir)), true));
    }
}
