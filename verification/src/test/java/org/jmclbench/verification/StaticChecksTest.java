package org.jmclbench.verification;

import org.jmclbench.verification.bytecode.AbortPollCheck;
import org.jmclbench.verification.bytecode.AllocationCheck;
import org.jmclbench.verification.bytecode.ClassPool;
import org.jmclbench.verification.bytecode.GuardedFieldCheck;
import org.jmclbench.verification.bytecode.Violation;
import org.jmclbench.verification.seeded.AllocatingRelease;
import org.jmclbench.verification.seeded.CleanRelease;
import org.jmclbench.verification.seeded.GuardedCounter;
import org.jmclbench.verification.seeded.PollingJob;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.List;
import java.util.Set;
import java.util.TreeSet;
import java.util.stream.Collectors;
import java.util.stream.IntStream;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The static checks report exactly the seeded violations (the lines marked VIOLATION in the
 * seeded sources), as class:method:line, and nothing in the clean code beside them.
 */
class StaticChecksTest {
    private static ClassPool pool;

    @BeforeAll
    static void readClasses() throws IOException {
        pool = ClassPool.of(List.of(Paths.get("target", "test-classes")));
    }

    @Test
    void allocationCheckReportsEveryAllocationReachableFromTheSeededRelease() throws IOException {
        List<Violation> v = new AllocationCheck(pool, n -> !n.endsWith("/SeededLayer"))
                .check(n -> n.endsWith("/" + AllocatingRelease.class.getSimpleName()));
        assertEquals(markedLines(AllocatingRelease.class), lines(v), v.toString());
        for (String kind : List.of("array clone", "enum values()", "a JDK call this rule does not know",
                "calls org.jmclbench.verification.seeded.SeededLayer.snapshot")) {
            assertTrue(v.stream().anyMatch(x -> x.what().startsWith(kind)), kind + " in " + v);
        }
        assertTrue(v.stream().anyMatch(x -> x.method().startsWith("lambda$") && x.what().startsWith("newarray")),
                v.toString());
        assertTrue(v.stream().anyMatch(x -> x.location().contains("$Table:<clinit>")), v.toString());
        assertTrue(v.stream().anyMatch(x -> x.location().equals(AllocatingRelease.class.getName() + "$AllocatingStep:apply:"
                + x.line()) && x.what().startsWith("anewarray")), v.toString());
        assertTrue(v.stream().anyMatch(x -> x.what().startsWith("string concatenation")), v.toString());
        assertTrue(v.stream().anyMatch(x -> x.what().startsWith("lambda")), v.toString());
        assertTrue(v.stream().anyMatch(x -> x.what().startsWith("boxing")), v.toString());
    }

    @Test
    void allocationCheckIsSilentOnACleanRelease() {
        List<Violation> v = new AllocationCheck(pool).check(n -> n.endsWith("/" + CleanRelease.class.getSimpleName()));
        assertEquals(List.of(), v);
    }

    @Test
    void abortPollCheckReportsExactlyTheUnpolledLoops() throws IOException {
        List<Violation> v = new AbortPollCheck(pool).check().stream()
                .filter(x -> x.className().equals(PollingJob.class.getName())).toList();
        assertEquals(markedLines(PollingJob.class), lines(v), v.toString());
        String job = PollingJob.class.getName();
        assertEquals(Set.of(job + ":update", job + ":siblings", job + ":wide", job + ":sparse", job + ":normalise",
                job + ":walk"),
                v.stream().map(x -> x.className() + ":" + x.method()).collect(Collectors.toSet()));
        // The strides read from the guards: (pollMask << 2) | 3 is four intervals, i % 128 two.
        assertTrue(v.stream().anyMatch(x -> x.method().equals("wide") && x.what().contains("every 256 particle steps")),
                v.toString());
        assertTrue(v.stream().anyMatch(x -> x.method().equals("sparse") && x.what().contains("every 128 particle steps")),
                v.toString());
        assertTrue(v.stream().anyMatch(x -> x.method().equals("walk") && x.what().contains("left i ")), v.toString());
    }

    @Test
    void guardedFieldCheckReportsExactlyTheAccessesOutsideTheMonitor() throws IOException {
        List<Violation> v = new GuardedFieldCheck(pool, n -> n.endsWith("/" + GuardedCounter.class.getSimpleName()))
                .check();
        assertEquals(markedLines(GuardedCounter.class), lines(v), v.toString());
    }

    private static Set<Integer> lines(List<Violation> v) {
        return v.stream().map(Violation::line).collect(Collectors.toCollection(TreeSet::new));
    }

    /** The lines of a seeded source marked "// VIOLATION". */
    private static Set<Integer> markedLines(Class<?> c) throws IOException {
        Path src = Paths.get("src", "test", "java", c.getName().replace('.', '/') + ".java");
        List<String> lines = Files.readAllLines(src);
        return IntStream.range(0, lines.size()).filter(i -> lines.get(i).contains("// VIOLATION"))
                .mapToObj(i -> i + 1).collect(Collectors.toCollection(TreeSet::new));
    }
}
