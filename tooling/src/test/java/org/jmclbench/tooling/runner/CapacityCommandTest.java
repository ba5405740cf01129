package org.jmclbench.tooling.runner;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import org.jmclbench.tooling.Fixtures;
import org.jmclbench.tooling.report.BreakdownRatio;
import org.jmclbench.tooling.store.StoredRuns;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The capacity command end to end on fake runtimes whose jobs start missing deadlines at a known
 * particle count: the search brackets that count to within 10%, records every probe as queue runs
 * in the store, and gives the ratio to the C baseline.
 */
class CapacityCommandTest {

    @TempDir
    Path dir;

    @Test
    void aCountMissedInTheOneRepetitionSaysOneRun() throws Exception {
        Fixtures.home(dir);
        String nativeBaseline = Fixtures.fakeJava(dir, "c", "breaks-at-2000", 0, null, 17).toString();
        Fixtures.CliResult r = Fixtures.cli("capacity", "--runtimes", "native", "--native", nativeBaseline, "--datasets", "tiny",
                "--repeat", "1", "--from", "1600", "--max", "3200", "--db", dir.resolve("results/one.db").toString());
        assertEquals(0, r.exitCode(), r.out() + r.err());
        assertTrue(r.out().contains("at 3200 particles: a job missed its deadline in 1 of 1 run\n"), r.out());
        assertFalse(r.out().contains("1 of 1 runs"), r.out());
    }

    @Test
    void bracketsEachBreakdownLoadAndRecordsEveryProbe() throws Exception {
        Fixtures.home(dir);
        String jvm = Fixtures.fakeJava(dir, "a", "breaks-at-1000", 0, null, 17).toString();
        String nativeBaseline = Fixtures.fakeJava(dir, "c", "breaks-at-2000", 0, null, 17).toString();
        Path db = dir.resolve("results/results.db");
        Fixtures.CliResult r = Fixtures.cli("capacity", "--java", jvm, "--runtimes", "native", "--native", nativeBaseline,
                "--datasets", "tiny", "--repeat", "2", "--from", "100", "--max", "12800", "--db", db.toString());
        assertEquals(0, r.exitCode(), r.out() + r.err());

        // native: 100..1600 hold, 3200 fails, then 2263 fails, 1903 holds, 2075 fails: [1903, 2075]
        Matcher c = row("native").matcher(r.out());
        assertTrue(c.find(), r.out());
        assertEquals("1903", c.group(1));
        assertEquals("2075", c.group(2));
        assertEquals("bracketed", c.group(3));
        assertEquals("a job missed its deadline in 2 of 2 runs", c.group(5), "the table says why the upper count failed");
        // the JVM breaks at 1000: [951, 1037], half of C's load
        Matcher a = row("fake-17").matcher(r.out());
        assertTrue(a.find(), r.out());
        int low = Integer.parseInt(a.group(1));
        int high = Integer.parseInt(a.group(2));
        assertTrue(low < 1000 && high >= 1000 && high <= low * 1.1, low + " " + high);
        // its load is in [951, 1037), C's in [1903, 2075): the ratio in [951/2075, 1037/1903]
        assertEquals(String.format(java.util.Locale.ROOT, "%.2f-%.2fx", low / 2075.0, high / 1903.0), a.group(4));

        try (StoredRuns stored = StoredRuns.open(db, "--db")) {
            assertTrue(stored.runs().stream().allMatch(x -> x.policy.equals("queue")));
            // each probe's two repetitions, once: a rerun finds them all done
            long nativeRuns = stored.runs().stream().filter(x -> x.runtime.equals("native")).count();
            assertEquals(2 * 9, nativeRuns, "9 probes of native, 2 repetitions each");
        }
        Fixtures.CliResult again = Fixtures.cli("capacity", "--java", jvm, "--runtimes", "native", "--native", nativeBaseline,
                "--datasets", "tiny", "--repeat", "2", "--from", "100", "--max", "12800", "--db", db.toString());
        assertEquals(0, again.exitCode(), again.err());
        assertTrue(again.out().contains("1903"), again.out());
    }

    @Test
    void aCountTheRuntimeCannotRunBoundsTheSearchAndEachProbeSaysWhy() throws Exception {
        Fixtures.home(dir);
        String jvm = Fixtures.fakeJava(dir, "a", "limit-at-1000", 0, null, 17).toString();
        Fixtures.CliResult r = Fixtures.cli("capacity", "--java", jvm, "--datasets", "tiny", "--repeat", "1", "--from", "100",
                "--max", "12800", "--db", dir.resolve("results/results.db").toString());
        assertEquals(0, r.exitCode(), r.out() + r.err());
        assertTrue(r.out().contains(" at 800 particles: every job by its deadline\n"), r.out());
        assertTrue(r.out().contains(" at 1600 particles: unsupported: --particles 1600: the fake VM holds at most 1000 particles\n"),
                r.out());
        // 1600, 1131 and 1037 are past the limit, 951 is not: [951, 1037]
        Matcher a = row("fake-17").matcher(r.out());
        assertTrue(a.find(), r.out());
        assertEquals("951", a.group(1));
        assertEquals("1037", a.group(2));
    }

    @Test
    void aRatioToALoadThatHeldToTheMaxIsABound() {
        CapacitySearch c = new CapacitySearch(100, 200);
        c.record(100, null);
        c.record(200, null);
        CapacitySearch jvm = new CapacitySearch(100, 200);
        jvm.record(100, null);
        jvm.record(200, "a job missed its deadline in 1 of 3 runs");
        // Java's load is in [100, 200), C's at least 200: the ratio is below 200/200 (it said "<= 0.50x",
        // the held counts' ratio, which a Java load of 199 would have broken)
        assertEquals("<= 1.00x", CapacityCommand.ratio(jvm, c), "C's breakdown is above the max: Java's ratio is at most this");
        assertEquals("1.00x", CapacityCommand.ratio(c, c));
        assertEquals(">= 1.00x", CapacityCommand.ratio(c, jvm));
    }

    /** Two brackets bound the ratio of the loads between holds over C's fails and fails over C's holds. */
    @Test
    void aRatioOfTwoBracketsIsTheIntervalTheyAllow() {
        assertEquals("0.45-0.55x", BreakdownRatio.of(100, 110, 200, 220, false));
        // two 10% brackets around one load: not "1.00x"
        assertEquals("0.91-1.10x", BreakdownRatio.of(1000, 1100, 1000, 1100, false));
        assertEquals("? (both held at every count)", BreakdownRatio.of(1000, null, 500, null, false));
        assertEquals("", BreakdownRatio.of(null, 100, 500, 550, false), "held at no count: no ratio");
    }

    /**
     * Measured on the shared VM: two searches of native on the same 3 s dataset bracketed it at
     * [8724, 9514] and [11314, 12338], the first with 11314 and 16000 each held in 1 of 2
     * repetitions above its failing 9514. A count above the failing one that held in some
     * repetition is said, so the bracket does not read as sharper than its runs.
     */
    @Test
    void aCountAboveTheFailingOneThatHeldInSomeRepetitionIsSaidNotMonotone() {
        CapacitySearch noisy = new CapacitySearch(100, 1600);
        CapacitySearch sharp = new CapacitySearch(100, 1600);
        for (CapacitySearch s : java.util.List.of(noisy, sharp)) {
            for (int n = s.next(); n > 0; n = s.next()) {
                // fails from 260 on, in every repetition but one at 400 in the noisy search
                int held = n < 260 ? 2 : n == 400 && s == noisy ? 1 : 0;
                s.record(new CapacitySearch.Probe(n, held == 2 ? null : "a job missed its deadline in " + (2 - held) + " of 2 runs",
                        held, 2));
            }
        }
        assertEquals(java.util.List.of(400), noisy.heldAboveHigh().stream().map(CapacitySearch.Probe::particles).toList());
        assertEquals(noisy.high(), sharp.high(), "the same bracket either way");
        java.util.Map<CapacityCommand.Configuration, CapacitySearch> searches = new java.util.LinkedHashMap<>();
        searches.put(new CapacityCommand.Configuration("fake-17", "default", "javase", "preallocated"), noisy);
        searches.put(new CapacityCommand.Configuration("native", "default", "native", "preallocated"), sharp);
        java.io.ByteArrayOutputStream bytes = new java.io.ByteArrayOutputStream();
        CapacityCommand.print(new java.io.PrintStream(bytes, true, java.nio.charset.StandardCharsets.UTF_8), searches);
        String out = bytes.toString(java.nio.charset.StandardCharsets.UTF_8);
        assertTrue(out.contains("Not monotone: fake-17 javase preallocated failed at " + noisy.high()
                + ", yet above it 400 held in 1 of 2 repetitions:"), out);
        assertFalse(out.contains("Not monotone: native"), out);
    }

    /** A configuration is compared with the C baseline of its own OS profile and memory style, not the first C row. */
    @Test
    void eachRowIsComparedWithTheCBaselineOfItsProfileAndMemoryStyle() {
        java.util.Map<CapacityCommand.Configuration, CapacitySearch> searches = new java.util.LinkedHashMap<>();
        searches.put(new CapacityCommand.Configuration("native", "default", "native", "preallocated"), bracket(1600));
        searches.put(new CapacityCommand.Configuration("native", "fifo", "native", "preallocated"), bracket(3200));
        searches.put(new CapacityCommand.Configuration("native", "default", "native", "allocating"), bracket(800));
        searches.put(new CapacityCommand.Configuration("fake-17", "g1+fifo", "javase", "preallocated"), bracket(1600));
        searches.put(new CapacityCommand.Configuration("fake-17", "g1", "javase", "allocating"), bracket(1600));
        searches.put(new CapacityCommand.Configuration("fake-17", "g1", "scj", "scoped"), bracket(1600));
        java.io.ByteArrayOutputStream bytes = new java.io.ByteArrayOutputStream();
        CapacityCommand.print(new java.io.PrintStream(bytes, true, java.nio.charset.StandardCharsets.UTF_8), searches);
        String out = bytes.toString(java.nio.charset.StandardCharsets.UTF_8);
        assertEquals(between(searches, "fake-17", "g1+fifo", "javase", "preallocated", "fifo", "preallocated"),
                ratioOf(out, "fake-17/g1+fifo javase preallocated"), "vs native fifo: " + out);
        assertEquals(between(searches, "fake-17", "g1", "javase", "allocating", "default", "allocating"),
                ratioOf(out, "fake-17/g1 javase allocating"), "vs native allocating: " + out);
        assertEquals(between(searches, "fake-17", "g1", "scj", "scoped", "default", "preallocated"),
                ratioOf(out, "fake-17/g1 scj scoped"), "no C scoped: vs native preallocated: " + out);
        assertEquals("1.00x", ratioOf(out, "native/fifo native preallocated"), out);
    }

    /** The ratio interval of one configuration's bracket over one native configuration's. */
    private static String between(java.util.Map<CapacityCommand.Configuration, CapacitySearch> searches, String runtime,
                                  String profile, String engine, String memory, String cProfile, String cMemory) {
        CapacitySearch s = searches.get(new CapacityCommand.Configuration(runtime, profile, engine, memory));
        CapacitySearch c = searches.get(new CapacityCommand.Configuration("native", cProfile, "native", cMemory));
        return String.format(java.util.Locale.ROOT, "%.2f-%.2fx", (double) s.low() / c.high(), (double) s.high() / c.low());
    }

    private static CapacitySearch bracket(int low) {
        CapacitySearch s = new CapacitySearch(low, low * 2);
        s.record(low, null);
        s.record(low * 2, "a job missed its deadline in 1 of 1 runs");
        int n;
        while ((n = s.next()) > 0) {
            s.record(n, "a job missed its deadline in 1 of 1 runs");
        }
        return s;
    }

    private static String ratioOf(String out, String label) {
        Matcher m = Pattern.compile("(?m)^  " + Pattern.quote(label) + "\\s+\\S+\\s+\\S+\\s+\\S+\\s+((?:[<>]= )?\\S+x)").matcher(out);
        return m.find() ? m.group(1) : "no ratio";
    }

    @Test
    void aBadRangeIsOneLineAndExitTwo() {
        Fixtures.CliResult r = Fixtures.cli("capacity", "--from", "500", "--max", "100");
        assertEquals(2, r.exitCode());
        assertEquals("jmclbench: --from/--max: need 1 <= from <= max, got 500 and 100", r.err().strip());
    }

    @Test
    void aListOfDatasetsIsOneLineAndExitTwo() throws Exception {
        Fixtures.home(dir);
        Files.createDirectories(dir.resolve("data"));
        copyTree(dir.resolve("data/tiny"), dir.resolve("data/tiny2"));
        Path db = dir.resolve("results/results.db");
        Fixtures.CliResult r = Fixtures.cli("capacity", "--java", Fixtures.fakeJava(dir, "a", "ok", 0, null, 17).toString(),
                "--datasets", "tiny,tiny2", "--repeat", "1", "--from", "100", "--max", "100", "--db", db.toString());
        assertEquals(2, r.exitCode(), r.out() + r.err());
        assertEquals("jmclbench: --datasets: a search takes one dataset, got 'tiny,tiny2'", r.err().strip());
        assertFalse(Files.exists(db), "nothing recorded");
    }

    private static void copyTree(Path from, Path to) throws Exception {
        Files.createDirectories(to);
        try (var files = Files.list(from)) {
            for (Path f : files.toList()) {
                Files.copy(f, to.resolve(f.getFileName()));
            }
        }
    }

    private static Pattern row(String runtime) {
        // configuration, holds at, fails at, search, vs C (a bound has "<= "), why it fails there
        return Pattern.compile("(?m)^  " + Pattern.quote(runtime)
                + "\\S* [^\\n]*?\\s(\\d+|none)\\s+(\\d+|none)\\s+(\\S+)\\s+((?:[<>]= )?\\S*)\\s*(.*)$");
    }
}
