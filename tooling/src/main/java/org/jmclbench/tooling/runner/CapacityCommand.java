package org.jmclbench.tooling.runner;

import java.io.PrintStream;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.Callable;
import java.util.function.IntFunction;
import java.util.stream.Collectors;

import org.jmclbench.tooling.cli.Counts;
import org.jmclbench.tooling.report.BreakdownRatio;
import org.jmclbench.tooling.doctor.Doctor;
import org.jmclbench.tooling.runtime.JmclbenchPaths;
import org.jmclbench.tooling.runtime.Profile;
import org.jmclbench.tooling.runtime.RuntimeDiscovery;
import org.jmclbench.tooling.runtime.RuntimeKind;
import org.jmclbench.tooling.store.MachineInfo;
import org.jmclbench.tooling.store.RunRecorder;
import org.jmclbench.tooling.store.RunRow;
import org.jmclbench.tooling.store.StoredRun;
import org.jmclbench.tooling.store.StoredRuns;

import com.fasterxml.jackson.databind.JsonNode;

import picocli.CommandLine.Command;
import picocli.CommandLine.IModelTransformer;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

/**
 * The breakdown load of each configuration (issue: metrics that answer the real-time question):
 * the largest particle count at which every job of both tasks completes by its deadline under
 * {@code queue} in every repetition, and the smallest at which one does not, found by
 * {@link CapacitySearch}. Every probe is a matrix cell run into the store like any other (so the
 * search resumes, and the report reads the same runs); the bracket is printed with the interval of
 * its ratio to the C baseline's ({@link BreakdownRatio}) when {@code native} is searched too.
 */
@Command(name = "capacity", mixinStandardHelpOptions = true,
        header = "Finds each configuration's breakdown load (queue policy).", sortOptions = false,
        description = {"Finds each configuration's breakdown load: the largest particle count at which every job of both "
                + "tasks completes by its deadline under the queue policy in every repetition, and the smallest at which "
                + "one does not, by a geometric then bisecting search to within 10%%. Every probe is a run in the store; "
                + "rerunning the same command resumes. Exit 0 when every search ended, 2 for bad input."},
        footer = {"", "Example: capacity --runtimes native,temurin-25 --engines javase,scj --repeat 3 --from 100 --max 102400"},
        modelTransformer = CapacityCommand.Settings.class)
public final class CapacityCommand implements Callable<Integer> {

    @Spec
    CommandSpec commandSpec;

    // The matrix settings SHARED come first (Settings), then:
    @Option(names = "--datasets", paramLabel = "NAME", description = "one dataset (default: match-short)")
    String dataset;
    @Option(names = "--repeat", paramLabel = "N", description = "repetitions of each probe; one late job in any fails the count (default: 3)")
    String repeat = "3";
    @Option(names = "--from", paramLabel = "N", description = "the first particle count probed (default: 100)")
    int from = 100;
    @Option(names = "--max", paramLabel = "N", description = "the largest particle count probed (default: 102400)")
    int max = 102_400;

    /** The matrix settings a capacity search takes as they are. */
    static final List<String> SHARED = List.of("runtimes", "java", "profiles", "engines", "memory", "time-scale", "timeout",
            "db", "native");

    /** Adds the options of the {@link #SHARED} settings. */
    static final class Settings implements IModelTransformer {
        @Override
        public CommandSpec transform(CommandSpec command) {
            return SettingOptions.add(command, 0, SHARED);
        }
    }

    /** One configuration under search: runtime, profile, engine and memory style. */
    record Configuration(String runtime, String profile, String engine, String memory) {
        static Configuration of(PlannedRun r) {
            return new Configuration(r.runtime().name(), r.profile().name(), r.engine(), r.memory());
        }

        String label() {
            return runtime + ("default".equals(profile) ? "" : "/" + profile) + " " + engine + " " + memory;
        }
    }

    @Override
    public Integer call() throws Exception {
        if (from < 1 || max < from) {
            throw new org.jmclbench.tooling.cli.BadUsageException("--from/--max: need 1 <= from <= max, got " + from + " and " + max);
        }
        if (dataset != null && dataset.contains(",")) {
            // a configuration's probe would hold the runs of every dataset at once, counted as its repetitions
            throw new org.jmclbench.tooling.cli.BadUsageException("--datasets: a search takes one dataset, got '" + dataset + "'");
        }
        String command = "jmclbench capacity " + String.join(" ", commandSpec.commandLine().getParseResult().originalArgs());
        print(System.out, search(this::spec, from, max, command, System.out));
        return 0;
    }

    /**
     * Searches the breakdown load of every configuration of {@code at}'s matrices, one configuration
     * after the other, each probe run into the store (so a rerun resumes); {@code at(n)} is the
     * matrix of every configuration at {@code n} particles under queue. Used by capacity and by
     * evaluate's breakdown sections.
     */
    static Map<Configuration, CapacitySearch> search(IntFunction<MatrixSpec> at, int from, int max, String command,
                                                     PrintStream out) throws Exception {
        Path home = JmclbenchPaths.home();
        MachineInfo machine = MachineInfo.current();
        MatrixSpec first = at.apply(from);
        ResolvedMatrix all = MatrixPlanner.resolve(first, RuntimeDiscovery::discover, home, machine);
        MatrixPlanner.prepareHvm(first, all, home); // every probe's runtimes and profiles are these
        List<Configuration> configurations = all.plan().stream().map(Configuration::of).distinct().toList();
        Map<Configuration, CapacitySearch> searches = new LinkedHashMap<>();
        configurations.forEach(c -> searches.put(c, new CapacitySearch(from, max)));
        try (RunRecorder store = RunRecorder.open(all.db(), "--db")) {
            store.saveMachine(machine, Doctor.toJson(Doctor.system().run()));
            for (Map.Entry<Configuration, CapacitySearch> e : searches.entrySet()) {
                Configuration c = e.getKey();
                CapacitySearch search = e.getValue();
                for (int n = search.next(); n > 0; n = search.next()) {
                    ResolvedMatrix m = MatrixPlanner.resolve(at.apply(n), RuntimeDiscovery::discover, home, machine);
                    MatrixRunner runner = MatrixRunner.begin(m, store, machine, command, home, JmclbenchPaths.workloadJar());
                    List<PlannedRun> mine = m.plan().stream().filter(r -> Configuration.of(r).equals(c)).toList();
                    Set<String> keys = mine.stream().map(PlannedRun::runKey).collect(Collectors.toSet());
                    runner.run(runner.remaining(false).stream().filter(r -> keys.contains(r.runKey())).toList(),
                            Progress.forConsole(out));
                    String notHeld = notHeld(all.db(), keys);
                    search.record(new CapacitySearch.Probe(n, notHeld, held(all.db(), keys), keys.size()));
                    out.printf(Locale.ROOT, "capacity: %s at %d particles: %s%n", c.label(), n,
                            notHeld == null ? "every job by its deadline" : notHeld);
                }
            }
        }
        return searches;
    }

    /**
     * Why the runs of these keys do not hold the load, in a few words (the runtime cannot run the
     * count, runs failed, a job missed its deadline); null when every run completed and no job of
     * any missed its deadline.
     */
    static String notHeld(Path db, Set<String> runKeys) {
        try (StoredRuns stored = StoredRuns.open(db, "--db")) {
            List<StoredRun> runs = stored.runs().stream().filter(r -> runKeys.contains(r.runKey)).toList();
            String of = " of " + Counts.of(runKeys.size(), "run");
            if (runs.size() < runKeys.size()) {
                return (runKeys.size() - runs.size()) + of + " not in the store";
            }
            StoredRun unsupported = runs.stream().filter(r -> RunRow.UNSUPPORTED.equals(r.status)).findFirst().orElse(null);
            if (unsupported != null) {
                return "unsupported: " + unsupported.failure;
            }
            long failed = runs.stream().filter(r -> !r.ok()).count();
            if (failed > 0) {
                return failed + of + " failed or timed out";
            }
            long missed = runs.stream().filter(r -> deadlineMisses(r.summary()) > 0).count();
            return missed == 0 ? null : "a job missed its deadline in " + missed + of;
        }
    }

    /** How many runs of these keys completed with every job by its deadline. */
    static int held(Path db, Set<String> runKeys) {
        try (StoredRuns stored = StoredRuns.open(db, "--db")) {
            return (int) stored.runs().stream().filter(r -> runKeys.contains(r.runKey) && r.ok()
                    && deadlineMisses(r.summary()) == 0).count();
        }
    }

    /** tasks.all.deadlineMisses, or late + skipped + terminated from a summary written before that field. */
    static long deadlineMisses(JsonNode summary) {
        JsonNode all = summary.path("tasks").path("all");
        if (all.has("deadlineMisses")) {
            return all.get("deadlineMisses").asLong();
        }
        return all.path("late").asLong(1) + all.path("skipped").asLong() + all.path("terminated").asLong();
    }

    static void print(PrintStream out, Map<Configuration, CapacitySearch> searches) {
        out.println("breakdown load (queue; every job of both tasks by its deadline in every repetition):");
        out.printf(Locale.ROOT, "  %-40s %10s %10s %-14s %-10s %s%n", "configuration", "holds at", "fails at", "search", "vs C",
                "why it fails there");
        for (Map.Entry<Configuration, CapacitySearch> e : searches.entrySet()) {
            CapacitySearch s = e.getValue();
            CapacitySearch c = baseline(searches, e.getKey());
            out.println(String.format(Locale.ROOT, "  %-40s %10s %10s %-14s %-10s %s", e.getKey().label(),
                    s.low() == null ? "none" : s.low(), s.high() == null ? "none" : s.high(), s.status().label, ratio(s, c),
                    s.highNotHeld() == null ? "" : s.highNotHeld()).stripTrailing());
        }
        out.println("Where the count above a bracket failed by one late job in one run, a repeated search may move the bracket"
                + " a step: such brackets, and their ratios to C, are not separated comparisons.");
        searches.forEach((c, s) -> {
            List<CapacitySearch.Probe> above = s.heldAboveHigh();
            if (!above.isEmpty()) {
                out.println("Not monotone: " + c.label() + " failed at " + s.high() + ", yet above it "
                        + above.stream().map(p -> p.particles() + " held in " + p.held() + " of " + Counts.of(p.repetitions(), "repetition"))
                                .collect(Collectors.joining(", "))
                        + ": its misses near the bracket are chance, so a repeated search may bracket it elsewhere, even"
                        + " more than a step away (more --repeat, or a quieter machine, narrows that).");
            }
        });
    }

    /**
     * The C baseline's search for {@code of}: native with the OS part of its profile (fifo, pinned)
     * and its memory style, else preallocated (the SCJ engine's scoped has no C counterpart); null
     * when native was not searched so.
     */
    static CapacitySearch baseline(Map<Configuration, CapacitySearch> searches, Configuration of) {
        String profile = Profile.parse(of.profile(), "--profiles").effectiveFor(RuntimeKind.NATIVE).name();
        Map<String, CapacitySearch> byMemory = new LinkedHashMap<>();
        searches.forEach((k, v) -> {
            if (k.runtime().equals("native") && k.profile().equals(profile)) {
                byMemory.putIfAbsent(k.memory(), v);
            }
        });
        return byMemory.getOrDefault(of.memory(), byMemory.get(Engines.PREALLOCATED));
    }

    /** The breakdown load over C's, as far as the two brackets know them ({@link BreakdownRatio}). */
    static String ratio(CapacitySearch s, CapacitySearch c) {
        return c == null ? "" : BreakdownRatio.of(s.low(), s.high(), c.low(), c.high(), s == c);
    }

    /** The matrix of one probe: every configuration at {@code particles}, under queue. */
    private MatrixSpec spec(int particles) {
        MatrixSpec spec = new MatrixSpec();
        SettingOptions.apply(commandSpec, spec);
        SettingOptions.list(spec, "policies", List.of("queue"));
        SettingOptions.list(spec, "particles", List.of(String.valueOf(particles)));
        if (dataset != null) {
            SettingOptions.list(spec, "datasets", List.of(dataset));
        }
        SettingOptions.one(spec, "repeat", repeat);
        return spec;
    }
}
