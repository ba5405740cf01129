package org.jmclbench.rtsj.weaver;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import javax.realtime.AsynchronouslyInterruptedException;
import javax.realtime.Interruptible;
import javax.realtime.RealtimeThread;
import org.jmclbench.rtsjcompat.Atc;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Assertions;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.objectweb.asm.ClassReader;
import org.objectweb.asm.tree.AbstractInsnNode;
import org.objectweb.asm.tree.ClassNode;
import org.objectweb.asm.tree.MethodInsnNode;
import org.objectweb.asm.tree.MethodNode;

/**
 * The woven samples run on rtsj-compat: each asserts where the AIE was delivered. A delivery in
 * synchronized code, in a finally or in a non-AI method shows in the log (a line that must have
 * run is missing), and the finally rule is shown to be needed by a weaver without it.
 */
class WeaverTest {

    @AfterEach
    void nothingPending() {
        assertEquals(0, Atc.pendingThreads());
    }

    private static List<String> run(String scenario) {
        return run(new Weaver(), scenario);
    }

    /** Runs a woven sample in a doInterruptible on a RealtimeThread; returns its log. */
    private static List<String> run(Weaver weaver, String scenario) {
        List<String> log = Collections.synchronizedList(new ArrayList<>());
        Throwable[] failure = new Throwable[1];
        RealtimeThread t = new RealtimeThread() {
            @Override
            public void run() {
                try {
                    Class<?> c = new WovenLoader(weaver, Samples.class).loadClass(Samples.class.getName());
                    Interruptible sample = (Interruptible) c.getConstructor(String.class, List.class).newInstance(scenario, log);
                    assertTrue(new AsynchronouslyInterruptedException().doInterruptible(sample));
                } catch (Throwable e) {
                    failure[0] = e;
                }
            }
        };
        Assertions.assertTimeoutPreemptively(Duration.ofSeconds(60), () -> {
            t.start();
            t.join();
        });
        if (failure[0] != null) {
            throw new AssertionError(failure[0]);
        }
        return new ArrayList<>(log);
    }

    @Test
    void anAieFiredInALoopIsDeliveredAtOnce() {
        assertEquals(List.of("interrupted"), run("loop"));
    }

    @Test
    void inSynchronizedCodeTheAieWaitsForTheEndOfTheMonitorRegion() {
        assertEquals(List.of("start", "in monitor 0", "in monitor 1", "in monitor 2", "end of synchronized",
                "interrupted"), run("synchronized"));
    }

    @Test
    void anAieFiredInAMonitorRegionThatEndsTheLogicIsDeliveredNotLost() {
        // without a delivery point where the region ends, run returned into doInterruptible, which
        // cleared the pending AIE: fire() had said true, yet interruptAction never ran
        assertEquals(List.of("in monitor", "interrupted"), run("endsInSynchronized"));
    }

    @Test
    void inAFinallyTheAieWaitsForItsEnd() {
        assertEquals(List.of("try", "in finally 0", "in finally 1", "in finally 2", "end of finally",
                "interrupted"), run("finally"));
    }

    @Test
    void aWeaverWithoutTheFinallyRuleDeliversInsideTheFinallyAndTheTestSeesIt() {
        assertEquals(List.of("try", "interrupted"), run(new Weaver(false), "finally"));
    }

    @Test
    void inANonAiMethodTheAieWaitsUntilControlIsBackInAiCode() {
        assertEquals(List.of("in non-AI 0", "in non-AI 1", "in non-AI 2", "end of non-AI", "interrupted"),
                run("nonAi"));
    }

    @Test
    void anAiMethodCalledFromSynchronizedCodeIsInterruptibleItselfAsRtsjDefinesItLexically() {
        assertEquals(List.of("interrupted"), run("aiCalleeInSynchronized"));
    }

    @Test
    void aCaughtAieIsDeliveredAgainUntilCleared() {
        assertEquals(List.of("caught", "interrupted"), run("caughtNotCleared"));
        assertEquals(List.of("cleared", "caught", "after catch", "completed"), run("caughtAndCleared"));
    }

    @Test
    void anotherThreadsFireIsDeliveredAtTheNextBackwardBranch() {
        assertEquals(List.of("interrupted"), run("crossThread"));
    }

    /** Delivery points per method of the woven sample class. */
    private static Map<String, Integer> pointsPerMethod(byte[] woven) {
        ClassNode c = new ClassNode();
        new ClassReader(woven).accept(c, 0);
        Map<String, Integer> m = new TreeMap<>();
        for (MethodNode mn : c.methods) {
            int n = 0;
            for (AbstractInsnNode i : mn.instructions) {
                if (i instanceof MethodInsnNode && Weaver.POLL_OWNER.equals(((MethodInsnNode) i).owner)) {
                    n++;
                }
            }
            m.put(mn.name, n);
        }
        return m;
    }

    @Test
    void onlyAiEnabledMethodsGetDeliveryPointsAndWeavingTwiceChangesNothing() throws Exception {
        byte[] original = WovenLoader.original(Samples.class.getName());
        Weaver.Result r = new Weaver().weave(original);
        Map<String, Integer> points = pointsPerMethod(r.bytes);
        assertEquals(0, points.get("nonAi"));
        assertEquals(0, points.get("interruptAction"));
        assertEquals(0, points.get("log"));
        assertEquals(0, points.get("<init>"));
        assertTrue(points.get("loop") >= 3, points.toString());
        assertEquals(9, r.aiMethods, "run, loop, inSynchronized, inFinally, nonAiCaller, aiCallee, interruptibleLog, caught, crossThread");
        assertEquals(r.deliveryPoints, points.values().stream().mapToInt(Integer::intValue).sum());
        Weaver.Result again = new Weaver().weave(r.bytes);
        assertArrayEquals(r.bytes, again.bytes);
        assertEquals(0, again.deliveryPoints);
        // a rebuild reports what the class holds, not "0 AI-enabled methods"
        assertEquals(r.aiMethods, again.aiMethodsBefore);
        assertEquals(r.deliveryPoints, again.deliveryPointsBefore);
    }

    @Test
    void aRebuildCountsTheMethodsTheBuildWoveNotTheAbstractOnes() throws Exception {
        Weaver.Result r = new Weaver().weave(WovenLoader.original(Samples.WithAbstractStep.class.getName()));
        assertEquals(1, r.aiMethods, "steps; step has no code");
        Weaver.Result again = new Weaver().weave(r.bytes);
        assertEquals(r.aiMethods, again.aiMethodsBefore);
        assertEquals(r.deliveryPoints, again.deliveryPointsBefore);
    }

    @Test
    void aFileThatIsNotAClassIsOneLineOfBadInputNamingIt(@TempDir Path dir) throws Exception {
        Path bad = Files.createDirectories(dir.resolve("p")).resolve("Bad.class");
        Files.write(bad, "not a class\n".getBytes(StandardCharsets.UTF_8));
        Files.write(dir.resolve("p/Empty.class"), new byte[0]);
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        int code = Weaver.run(new String[] {dir.toString()}, new PrintStream(new ByteArrayOutputStream()), new PrintStream(err));
        assertEquals(2, code, err.toString());
        assertTrue(err.toString().startsWith("rtsj-weaver: " + bad + ": not a class file"), err.toString());
        assertEquals(1, err.toString().strip().split("\n").length, err.toString());
    }

    @Test
    void theSummarySaysWhatAnEarlierBuildWove() {
        assertEquals("2 AI-enabled methods, 7 delivery points", Weaver.summary(2, 7, 0, 0));
        assertEquals("2 AI-enabled methods, 7 delivery points (woven by an earlier build)", Weaver.summary(0, 0, 2, 7));
        assertEquals("3 AI-enabled methods, 9 delivery points (1 of the methods woven by an earlier build)",
                Weaver.summary(2, 7, 1, 2));
    }

    @Test
    void theCommandLineRejectsWhatIsNotADirectory() {
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        int code = Weaver.run(new String[] {"no/such/dir"}, new PrintStream(new ByteArrayOutputStream()), new PrintStream(err));
        assertEquals(2, code);
        assertTrue(err.toString().contains("not a directory: no/such/dir"), err.toString());
        assertFalse(err.toString().contains("\n\n"));
    }
}
