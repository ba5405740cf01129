package org.jmclbench.tooling.report;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import org.jmclbench.tooling.Fixtures;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** compare on fixture stores: both modes, the verdicts, and bad input. */
class CompareCommandTest {

    @TempDir
    static Path dir;
    static Path a;
    static Path b;

    @BeforeAll
    static void stores() throws Exception {
        FixtureDb fa = new FixtureDb();
        fa.policies = List.of("skip");
        fa.particles = List.of(400);
        fa.repetitions = 10;
        a = ReportFixtures.write(fa, dir, "a.db");
        FixtureDb fb = new FixtureDb();
        fb.policies = List.of("skip");
        fb.particles = List.of(400);
        fb.repetitions = 10;
        fb.seed = 2;
        // Machine B is twice as slow for every runtime.
        fb.configs = new ArrayList<>(fa.configs.stream()
                .map(c -> new FixtureDb.Config(c.runtime(), c.profile(), c.version(), c.speed() * 2, c.status())).toList());
        b = ReportFixtures.write(fb, dir, "b.db");
    }

    static String[] run(int expectedExit, String... args) {
        Fixtures.CliResult r = Fixtures.cli(args);
        assertEquals(expectedExit, r.exitCode(), "stdout: " + r.out() + "\nstderr: " + r.err());
        return new String[] {r.out(), r.err()};
    }

    static String line(String table, String metric) {
        return table.lines().filter(l -> l.startsWith(metric)).findFirst().orElseThrow(() -> new AssertionError(metric + " in\n" + table));
    }

    /**
     * A row name with its load bracket selects the runs beside that load only, and the plain name the
     * idle runs only: loaded, noidle's jobs cost 3 times default's (task latency B/A about 2.9); idle,
     * half (about 0.6). Pooled, both would read about 2.1, with 6 runs a side; a name that leaves both
     * loads is asked to say which.
     */
    @Test
    void aLoadBracketSelectsTheLoadedRunsAndThePlainNameTheIdleOnes() throws Exception {
        FixtureDb f = new FixtureDb();
        f.policies = List.of("skip");
        f.particles = List.of(400);
        f.loads = List.of("none", "cpu");
        f.configs = List.of(new FixtureDb.Config("native", "default", "gcc 12.2.0", 1.0, "ok"),
                new FixtureDb.Config("native", "noidle", "gcc 12.2.0", 1.0, "ok"));
        f.costScale = java.util.Map.of("native/noidle", 0.5, "native/default [load cpu]", 2.0, "native/noidle [load cpu]", 6.0);
        Path db = ReportFixtures.write(f, dir, "bracket.db");
        String loaded = run(0, "compare", "--db", db.toString(), "--a", "native/default [load cpu]",
                "--b", "native/noidle [load cpu]")[0];
        assertTrue(loaded.contains("A: native/default [load cpu]") && loaded.contains("B: native/noidle [load cpu]"), loaded);
        assertTrue(loaded.contains("== match-short  skip  400 particles =="), loaded);
        assertEquals(2, line(loaded, "task latency mean").split("n=3 ", -1).length - 1, line(loaded, "task latency mean"));
        assertTrue(ratio(loaded, "task latency mean") > 2.5, line(loaded, "task latency mean"));
        String idle = run(0, "compare", "--db", db.toString(), "--a", "native/default", "--b", "native/noidle")[0];
        assertEquals(2, line(idle, "task latency mean").split("n=3 ", -1).length - 1, line(idle, "task latency mean"));
        assertTrue(ratio(idle, "task latency mean") < 1, line(idle, "task latency mean"));
        String err = run(2, "compare", "--db", db.toString(), "--a", "native", "--b", "native/noidle [load cpu]")[1];
        assertTrue(err.contains("--a: native has several configurations in " + db + ", say which: native/default, "
                + "native/default [load cpu], native/noidle, native/noidle [load cpu]"), err);
    }

    /** The B/A column of a metric's line: the number after the two cells, each ending in n=N. */
    private static double ratio(String table, String metric) {
        String l = line(table, metric);
        String afterCells = l.substring(l.lastIndexOf("n=")).replaceFirst("^n=\\d+\\s+", "");
        return Double.parseDouble(afterCells.split("\\s+")[0]);
    }

    @Test
    void runsAtTwoTimeScalesAreComparedByTheirRowNamesNeverPooled() throws Exception {
        // repetitions 7 to 10 made again by a second matrix at --time-scale 0.5 (telling no workload arguments, as the first)
        Path scaled = java.nio.file.Files.copy(a, dir.resolve("time-scales.db"));
        try (var c = java.sql.DriverManager.getConnection("jdbc:sqlite:" + scaled); var st = c.createStatement()) {
            st.execute("INSERT INTO matrices VALUES ('x-2', 'm-1', 'jmclbench matrix --time-scale 0.5', 8,"
                    + " '2026-11-22T03:00:00Z', '{\"timeScale\":0.5}')");
            st.execute("UPDATE runs SET matrix_id = 'x-2' WHERE repetition > 6");
        }
        String out = run(0, "compare", "--db", scaled.toString(), "--a", "native", "--b", "native [time scale 0.5]")[0];
        assertTrue(line(out, "missCount").contains(" n=6 ") && line(out, "missCount").contains(" n=4 "),
                "six repetitions at 1 against four at 0.5, not ten a side: " + line(out, "missCount"));
    }

    @Test
    void twoStoresWithNoSettingInCommonSayWhatEachSideHolds() throws Exception {
        // B measured every configuration again, at --time-scale 0.5: its rows are named apart from A's
        Path scaled = java.nio.file.Files.copy(b, dir.resolve("b-scaled.db"));
        try (var c = java.sql.DriverManager.getConnection("jdbc:sqlite:" + scaled); var st = c.createStatement()) {
            st.execute("UPDATE matrices SET spec_json = '{\"timeScale\":0.5}'");
        }
        String err = oneLine("compare", a.toString(), scaled.toString());
        assertTrue(err.contains("no setting (dataset, policy, particles, runtime) has runs in both A and B"), err);
        assertTrue(err.contains("A has match-short  skip  400 particles  native, ")
                && err.contains("B has match-short  skip  400 particles  native [time scale 0.5], "), err);
    }

    @Test
    void twoVersionsOfOneRuntimeAreComparedByTheirRowNamesNeverPooled() throws Exception {
        // temurin-17 updated to 17.0.16+8 before repetitions 7 to 10
        Path updated = java.nio.file.Files.copy(a, dir.resolve("two-versions.db"));
        try (var c = java.sql.DriverManager.getConnection("jdbc:sqlite:" + updated); var st = c.createStatement()) {
            st.execute("UPDATE runs SET runtime_version = '17.0.16+8' WHERE runtime = 'temurin-17' AND repetition > 6");
        }
        String out = run(0, "compare", "--db", updated.toString(), "--a", "temurin-17/g1 [17.0.15+6]", "--b",
                "temurin-17/g1 [17.0.16+8]")[0];
        assertTrue(line(out, "missCount").contains(" n=6 ") && line(out, "missCount").contains(" n=4 "),
                "six repetitions on 17.0.15 against four on 17.0.16, not ten a side: " + line(out, "missCount"));
        String err = run(2, "compare", "--db", updated.toString(), "--a", "temurin-17", "--b", "native")[1];
        assertTrue(err.contains("say which: temurin-17/g1 [17.0.15+6], temurin-17/g1 [17.0.16+8]"), err);
    }

    @Test
    void aConfigurationAgainstItselfIsRefusedNotComparedWithItsOwnRuns() {
        // the same runs on both sides measured nothing twice: no ratio, interval or verdict to print
        String err = run(2, "compare", "--db", a.toString(), "--a", "native", "--b", "native")[1];
        assertTrue(err.contains("--b: native names the same runs as --a native") && err.strip().lines().count() == 1, err);
        run(2, "compare", "--db", a.toString(), "--a", "temurin-25", "--b", "temurin-25/zgc");
    }

    @Test
    void oneStoreGivenAsBothDatabasesIsRefusedNotComparedWithItsOwnRuns() throws Exception {
        // the same file twice, or two paths to it: each configuration would meet its own runs
        Path other = dir.resolve("sub");
        java.nio.file.Files.createDirectories(other);
        String viaDots = other.resolve("..").resolve(a.getFileName()).toString();
        Path link = java.nio.file.Files.createSymbolicLink(dir.resolve("link-to-a.db"), a);
        for (String[] args : new String[][] {{a.toString(), a.toString()}, {a.toString(), viaDots}, {link.toString(), a.toString()},
                {a.toString(), a.toString(), "--a", "native"}, {a.toString(), a.toString(), "--a", "native", "--b", "native"}}) {
            List<String> cmd = new ArrayList<>(List.of("compare"));
            cmd.addAll(List.of(args));
            String[] r = run(2, cmd.toArray(String[]::new));
            assertTrue(r[1].contains("are the same store") && r[1].contains("the same runs") && r[1].strip().lines().count() == 1,
                    String.join(" ", args) + ": " + r[1]);
            assertTrue(r[0].isEmpty(), "nothing compared: " + r[0]);
        }
        // two configurations of that one store are two measurements, as with --db
        String out = run(0, "compare", a.toString(), a.toString(), "--a", "native", "--b", "temurin-17")[0];
        assertTrue(out.contains("task latency mean"), out);
    }

    /** A copy of a store, or a merge that holds it, brings A's own measurements to B: a ratio of 1 measured once. */
    @Test
    void aCopyOfAOrAMergeHoldingItIsRefusedAsB() throws Exception {
        Path copy = java.nio.file.Files.copy(a, dir.resolve("copy-of-a.db"));
        String err = run(2, "compare", a.toString(), copy.toString())[1];
        assertEquals("jmclbench: compare: B " + copy + " holds 30 runs of A " + a + " (the same run key and measured results:"
                + " a copy of A or a merge that holds it): each side must be measured apart", err.strip());
        Path merged = dir.resolve("merged/results.db");
        run(0, "merge", a.toString(), b.toString(), "--into", merged.toString());
        err = run(2, "compare", a.toString(), merged.toString())[1];
        assertTrue(err.contains("holds 30 runs of A"), err);
        // B's runs share A's keys (one matrix on two machines) but not A's measurements: these compare
        assertTrue(run(0, "compare", a.toString(), b.toString())[0].contains("task latency mean"));
    }

    /** A profile the JVM refused (its runs all unsupported) has nothing to compare: the runtime's name still chooses one. */
    @Test
    void aConfigurationWithoutACompletedRunDoesNotMakeARuntimeAmbiguous() throws Exception {
        FixtureDb f = new FixtureDb();
        f.policies = List.of("skip");
        f.particles = List.of(400);
        f.configs = List.of(new FixtureDb.Config("native", "", "gcc 12.2.0", 1.0, "ok"),
                new FixtureDb.Config("openjdk-17", "default", "17.0.9", 1.3, "ok"),
                new FixtureDb.Config("openjdk-17", "shenandoah", "17.0.9", 1.3, "unsupported"));
        Path db = ReportFixtures.write(f, dir, "refused-profile.db");
        String out = run(0, "compare", "--db", db.toString(), "--a", "native", "--b", "openjdk-17")[0];
        assertTrue(out.contains("B: openjdk-17") && out.contains("task latency mean"), out);
        // two measured profiles are still two candidates
        f.configs = List.of(f.configs.get(0), f.configs.get(1), new FixtureDb.Config("openjdk-17", "zgc", "17.0.9", 1.2, "ok"));
        Path two = ReportFixtures.write(f, dir, "two-profiles.db");
        String err = run(2, "compare", "--db", two.toString(), "--a", "native", "--b", "openjdk-17")[1];
        assertTrue(err.contains("say which: openjdk-17/default, openjdk-17/zgc"), err);
    }

    @Test
    void missCountIsNamedForTheJobsItCountsUnderEachPolicy() throws Exception {
        FixtureDb f = new FixtureDb();
        f.policies = List.of("skip", "terminate", "queue");
        f.particles = List.of(400);
        Path db = ReportFixtures.write(f, dir, "policies.db");
        String out = run(0, "compare", "--db", db.toString(), "--a", "native", "--b", "temurin-25/zgc")[0];
        for (String[] policyJobs : new String[][] {{"skip", "dropped jobs"}, {"terminate", "dropped or aborted jobs"},
                {"queue", "late jobs"}}) {
            String table = out.substring(out.indexOf("  " + policyJobs[0] + "  400 particles =="));
            assertTrue(line(table, "missCount").startsWith("missCount (" + policyJobs[1] + ") "), line(table, "missCount"));
        }
        // a miss ratio is a fraction of the task's released jobs, not a "ratio (ratio)"
        assertTrue(line(out, "predict miss ratio").startsWith("predict miss ratio (fraction of jobs) "), line(out, "predict miss ratio"));
    }

    @Test
    void twoDatabasesPairTheSameConfigurations() {
        String out = run(0, "compare", a.toString(), b.toString())[0];
        assertTrue(out.contains("== match-short  skip  400 particles  native =="), out);
        assertTrue(out.contains("== match-short  skip  400 particles  temurin-25/zgc =="), out);
        String latency = line(out.substring(out.indexOf("native ==")), "task latency mean");
        // Twice as slow: the ratio is about 2, its interval excludes 1 and ten runs against ten separate.
        String[] cols = latency.split("\\s{2,}");
        double ratio = Double.parseDouble(cols[3].trim());
        assertEquals(2.0, ratio, 0.15, latency);
        assertTrue(latency.endsWith("A lower than B (p < 0.001, n = 10 vs 10)"), latency);
        assertTrue(latency.matches(".* \\d\\.\\d{3} \\[\\d\\.\\d{3}, \\d\\.\\d{3}\\] n=10 .*"), "a bootstrap interval per side: " + latency);
    }

    @Test
    void oneDatabaseTwoRuntimesWithFilters() {
        String out = run(0, "compare", "--db", a.toString(), "--a", "native", "--b", "temurin-17/g1", "--policy", "skip",
                "--particles", "400")[0];
        assertTrue(out.contains("A: native") && out.contains("B: temurin-17/g1"), out);
        String latency = line(out, "task latency mean");
        double ratio = Double.parseDouble(latency.split("\\s{2,}")[3].trim());
        assertEquals(1.3, ratio, 0.1, latency);
        assertTrue(latency.matches(".*\\[\\d\\.\\d{3}, \\d\\.\\d{3}\\].*"), "a bootstrap interval: " + latency);
        // A runtime with a single profile is found by its runtime name alone.
        run(0, "compare", "--db", a.toString(), "--a", "native", "--b", "temurin-17");
    }

    /**
     * An engine registered with the workload only (the tests' runner.RegisteredProbeEngine) is an
     * engine in a configuration's name, not taken for a profile; so are native and hvm.
     */
    @Test
    void anEngineOfTheWorkloadsRegistryIsAnEngineOfAConfiguration() {
        assertTrue(CompareCommand.ENGINES.containsAll(List.of("registered-probe", "javase", "rtsj-atomic", "native", "hvm")),
                CompareCommand.ENGINES.toString());
    }

    @Test
    void tooFewRepetitionsSaySoAndRankNothing() throws Exception {
        FixtureDb f = new FixtureDb();
        f.policies = List.of("skip");
        f.particles = List.of(100);
        f.repetitions = 6;
        Path small = ReportFixtures.write(f, dir, "small.db");
        String out = run(0, "compare", "--db", small.toString(), "--a", "native", "--b", "temurin-25/zgc")[0];
        for (Metric m : CompareCommand.METRICS) {
            String row = line(out, m.label);
            // six runs a side of a runtime 1.3 times slower would have been "significant" before
            assertTrue(row.contains("not separated: n too small to separate (") && row.endsWith("n = 6 vs 6; 10 a side needed)"), row);
        }
        assertTrue(!out.contains("lower than"), out);
    }

    /**
     * A filter that leaves a side without runs is named: --policy, --particles or --dataset when the
     * configuration has runs but none under it, --a or --b only when the configuration itself is not
     * in the store; and a label with an rtsj engine names that engine, as with the other engines.
     */
    @Test
    void aFilterThatMatchesNoRunIsNamedNotBlamedOnA() throws Exception {
        String err = oneLine("compare", "--db", a.toString(), "--a", "native", "--b", "temurin-17", "--policy", "queue");
        assertTrue(err.startsWith("jmclbench: --policy: no run of --a native in " + a + " has policy 'queue' (its policies: skip)"), err);
        err = oneLine("compare", "--db", a.toString(), "--a", "native", "--b", "temurin-17", "--particles", "999");
        assertTrue(err.startsWith("jmclbench: --particles: no run of --a native in " + a + " has particles '999' (its particle counts: 400)"), err);
        err = oneLine("compare", "--db", a.toString(), "--a", "native", "--b", "temurin-17/zgc");
        assertTrue(err.startsWith("jmclbench: --b: no configuration temurin-17/zgc in " + a + " (known: native, temurin-17/g1, "), err);

        // B's store has no queue run: the filter is named, for B, not --a or --b
        FixtureDb f = new FixtureDb();
        f.policies = List.of("skip", "queue");
        f.particles = List.of(400);
        Path queue = ReportFixtures.write(f, dir, "queue.db");
        err = oneLine("compare", queue.toString(), b.toString(), "--policy", "queue");
        assertTrue(err.startsWith("jmclbench: --policy: no run of B in " + b + " has policy 'queue' (its policies: skip)"), err);
        err = oneLine("compare", queue.toString(), b.toString(), "--a", "native", "--b", "native", "--policy", "queue");
        assertTrue(err.startsWith("jmclbench: --policy: no run of --b native in " + b + " has policy 'queue' (its policies: skip)"), err);

        // the rtsj engines in a label, as javase and scj are
        FixtureDb e = new FixtureDb();
        e.policies = List.of("terminate");
        e.particles = List.of(400);
        e.configs = new ArrayList<>(List.of(
                new FixtureDb.Config("temurin-25", "g1", "25+36", 1.15, "ok", "javase", "preallocated"),
                new FixtureDb.Config("temurin-25", "g1", "25+36", 1.2, "ok", "rtsj", "preallocated"),
                new FixtureDb.Config("temurin-25", "g1", "25+36", 1.25, "ok", "rtsj-atomic", "preallocated")));
        Path engines = ReportFixtures.write(e, dir, "rtsj.db");
        String out = run(0, "compare", "--db", engines.toString(), "--a", "temurin-25/rtsj", "--b", "temurin-25/rtsj-atomic")[0];
        assertTrue(out.contains("A: temurin-25/rtsj\nB: temurin-25/rtsj-atomic"), out);
        out = run(0, "compare", "--db", engines.toString(), "--a", "temurin-25", "--b", "temurin-25/g1 / rtsj-atomic")[0];
        assertTrue(out.contains("== match-short  terminate  400 particles =="), out);
    }

    private static String oneLine(String... args) {
        String err = run(2, args)[1];
        assertEquals(1, err.strip().lines().count(), err);
        return err;
    }

    @Test
    void badInputIsOneLineAndExitTwo() {
        String err = run(2, "compare", "--db", a.toString(), "--a", "native", "--b", "no-such-jvm")[1];
        assertEquals(1, err.strip().lines().count(), err);
        assertTrue(err.contains("--b: unknown runtime 'no-such-jvm'") && err.contains("known: native"), err);
        err = run(2, "compare", dir.resolve("missing.db").toString(), b.toString())[1];
        assertEquals(1, err.strip().lines().count(), err);
        assertTrue(err.contains("missing.db: no such database"), err);
        err = run(2, "compare", a.toString())[1];
        assertEquals(1, err.strip().lines().count(), err);
        err = run(2, "compare", "--db", a.toString(), "--a", "native")[1];
        assertTrue(err.startsWith("jmclbench: --b:"), err);
        err = run(2, "compare", "--db", a.toString(), "--a", "native", "--b", "temurin-17", "--particles", "999")[1];
        assertEquals(1, err.strip().lines().count(), err);
    }
}
