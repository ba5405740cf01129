package org.jmclbench.tooling.report;

import java.io.IOException;
import java.io.PrintStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;
import java.util.TreeSet;
import java.util.concurrent.Callable;
import java.util.function.Function;
import java.util.stream.Collectors;

import org.jmclbench.tooling.cli.BadUsageException;
import org.jmclbench.tooling.cli.Counts;
import org.jmclbench.tooling.runner.Engines;
import org.jmclbench.tooling.store.StoredRun;
import org.jmclbench.tooling.store.StoredRuns;

import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;

/**
 * Compares two result sets metric by metric, like benchstat: means with their 95% bootstrap
 * intervals, the ratio B/A with its bootstrap interval, and per metric whether {@link Separation}'s
 * rule tells A and B apart ("not separated" otherwise: never a ranking the data do not carry).
 */
@Command(name = "compare", mixinStandardHelpOptions = true,
        header = "Compares two result sets metric by metric, like benchstat.",
        description = {"Compares two result sets metric by metric, like benchstat: A and B (mean [95%% bootstrap "
                + "interval]), the ratio B/A with its bootstrap 95%% CI (fixed seed) and whether one is lower: "
                + "only with at least 10 runs a side, Mann-Whitney U p < 0.05 and the ratio's interval "
                + "excluding 1; else \"not separated\" (\"n too small to separate\" below 10 runs a side).",
                "",
                "  compare A.db B.db      the same configurations in two databases (two machines)",
                "  compare --db X.db --a RUNTIME[/PROFILE][/ENGINE][/MEMORY] --b ...",
                "                         two configurations of one database, e.g.",
                "                         --a temurin-25 --b temurin-25/scj (Java SE vs SCJ)",
                "                         or a row name of the report, with its load bracket:",
                "                         --a 'native/default [load cpu]': the loaded runs only,",
                "                         --a native/default: the idle runs only",
                ""})
public final class CompareCommand implements Callable<Integer> {

    /** The metrics compared, in table order. */
    static final List<Metric> METRICS = List.of(Metric.MISS_COUNT, Metric.DEADLINE_MISSES, Metric.MISS_RATIO_PREDICT,
            Metric.MISS_RATIO_UPDATE, Metric.LATENCY_MEAN, Metric.LATENCY_P99, Metric.JITTER_MEAN, Metric.JITTER_P99, Metric.DEVIATION);

    @Parameters(arity = "0..2", paramLabel = "DB", description = "two databases, A then B")
    List<Path> databases = new ArrayList<>();

    @Option(names = "--db", paramLabel = "FILE", description = "one database holding both A and B")
    Path db;

    @Option(names = "--a", paramLabel = "RUNTIME[/PROFILE][/ENGINE][/MEMORY]",
            description = "configuration A (with --db; with two databases: A's filter); ENGINE javase, scj, ...; MEMORY preallocated, allocating, scoped;"
                    + " or a row name as the report shows it, e.g. 'native/default [load cpu]' (the plain name: the idle runs)")
    String a;

    @Option(names = "--b", paramLabel = "RUNTIME[/PROFILE][/ENGINE][/MEMORY]",
            description = "configuration B (with --db; with two databases: B's filter), named as --a")
    String b;

    @Option(names = "--policy", paramLabel = "POLICY", description = "only this policy (skip, terminate, queue)")
    String policy;

    @Option(names = "--particles", paramLabel = "N", description = "only this particle count")
    Integer particles;

    @Option(names = "--dataset", paramLabel = "NAME", description = "only this dataset")
    String dataset;

    PrintStream out = System.out;

    @Override
    public Integer call() throws BadUsageException {
        List<StoredRun> runsA;
        List<StoredRun> runsB;
        String nameA;
        String nameB;
        boolean pairByConfig;
        if (db != null) {
            if (!databases.isEmpty()) {
                throw new BadUsageException("--db: give either --db with --a/--b or two databases, not both");
            }
            if (a == null || b == null) {
                throw new BadUsageException((a == null ? "--a" : "--b") + ": needed with --db (RUNTIME[/PROFILE])");
            }
            try (StoredRuns store = StoredRuns.open(db, "--db")) {
                List<StoredRun> all = store.runs();
                runsA = choose(filtered(all), all, a, "--a", db);
                runsB = choose(filtered(all), all, b, "--b", db);
            }
            // runs against themselves give a ratio of 1 with a bootstrap interval around it, as if measured twice
            if (keys(runsA).equals(keys(runsB))) {
                throw new BadUsageException("--b: " + b + " names the same runs as --a " + a + " in " + db + ": nothing to compare");
            }
            nameA = a;
            nameB = b;
            pairByConfig = false;
        } else {
            if (databases.size() != 2) {
                throw new BadUsageException("compare: give two databases (A.db B.db) or --db FILE --a RUNTIME --b RUNTIME");
            }
            List<StoredRun> allA;
            List<StoredRun> allB;
            try (StoredRuns sa = StoredRuns.open(databases.get(0), "A");
                 StoredRuns sb = StoredRuns.open(databases.get(1), "B")) {
                allA = sa.runs();
                allB = sb.runs();
            }
            runsA = filtered(allA);
            runsB = filtered(allB);
            if (a == null && runsA.isEmpty() && !allA.isEmpty()) {
                throw noRunUnderTheFilters(allA, "A", databases.get(0));
            }
            if (b == null && runsB.isEmpty() && !allB.isEmpty()) {
                throw noRunUnderTheFilters(allB, "B", databases.get(1));
            }
            // one labelling for both sides, so that a configuration is named alike in A and B
            List<StoredRun> both = new ArrayList<>(runsA);
            both.addAll(runsB);
            StoredRun.labelEngines(both);
            if (a != null) {
                runsA = choose(runsA, allA, a, "--a", databases.get(0));
            }
            if (b != null) {
                runsB = choose(runsB, allB, b, "--b", databases.get(1));
            }
            nameA = databases.get(0) + (a == null ? "" : " " + a);
            nameB = databases.get(1) + (b == null ? "" : " " + b);
            pairByConfig = a == null || b == null;
        }
        Map<String, List<StoredRun>> groupsA = group(runsA, pairByConfig);
        Map<String, List<StoredRun>> groupsB = group(runsB, pairByConfig);
        // A's own measurements on the B side (one store given twice, a copy of A, a merge that holds
        // it) would compare runs with themselves: a ratio of 1 as if measured twice
        long shared = db == null ? sharedMeasurements(groupsA, groupsB) : 0;
        if (shared > 0 && sameFile(databases.get(0), databases.get(1))) {
            throw new BadUsageException("compare: A " + databases.get(0) + " and B " + databases.get(1) + " are the same store"
                    + " and each side would hold the same runs: nothing to compare (two configurations of one store:"
                    + " --db FILE --a CONFIG --b CONFIG)");
        }
        if (shared > 0) {
            throw new BadUsageException("compare: B " + databases.get(1) + " holds " + Counts.of(shared, "run")
                    + " of A " + databases.get(0) + " (the same run key and measured results: a copy of A or a merge"
                    + " that holds it): each side must be measured apart");
        }
        out.println("A: " + nameA);
        out.println("B: " + nameB);
        int compared = 0;
        for (Map.Entry<String, List<StoredRun>> e : groupsA.entrySet()) {
            List<StoredRun> gb = groupsB.get(e.getKey());
            if (gb == null) {
                continue;
            }
            out.println();
            out.println("== " + e.getKey() + " ==");
            printTable(e.getValue(), gb);
            compared++;
        }
        if (compared == 0) {
            // name what each side holds: rows apart by a setting (a time scale, a version) look alike otherwise
            throw new BadUsageException("compare: no setting (dataset, policy, particles" + (pairByConfig ? ", runtime" : "")
                    + ") has runs in both A and B" + (hasFilter() ? " with the given filters" : "")
                    + ": A has " + someOf(groupsA.keySet()) + "; B has " + someOf(groupsB.keySet()));
        }
        out.println();
        out.println("A, B: mean [95% percentile-bootstrap interval]; B/A CI: percentile bootstrap, " + Stats.BOOTSTRAP_RESAMPLES
                + " resamples, seed " + Stats.BOOTSTRAP_SEED + "; separated: at least " + Separation.MIN_REPETITIONS
                + " runs a side, two-sided Mann-Whitney U p < " + Stats.ALPHA + " and the B/A interval excluding 1"
                + " (docs/REPORT.md); n = completed runs.");
        return 0;
    }

    /** The first few of a side's settings, in order, and how many more there are. */
    private static String someOf(Set<String> settings) {
        List<String> sorted = settings.stream().sorted().toList();
        int shown = Math.min(3, sorted.size());
        String some = String.join(", ", sorted.subList(0, shown));
        return sorted.size() > shown ? some + " and " + (sorted.size() - shown) + " more" : some;
    }

    /** Whether two paths name one file (the same path, another spelling of it, a link to it). */
    private static boolean sameFile(Path x, Path y) {
        try {
            return Files.isSameFile(x, y);
        } catch (IOException e) {
            return false; // StoredRuns.open has read both: a path that cannot be resolved now is not known to be the other
        }
    }

    /** How many runs the settings both sides have hold on both sides, the very same measurement (key and results). */
    private static long sharedMeasurements(Map<String, List<StoredRun>> groupsA, Map<String, List<StoredRun>> groupsB) {
        long shared = 0;
        for (Map.Entry<String, List<StoredRun>> e : groupsA.entrySet()) {
            List<StoredRun> gb = groupsB.get(e.getKey());
            if (gb != null) {
                Set<List<String>> inB = gb.stream().map(CompareCommand::measurement).collect(Collectors.toSet());
                shared += e.getValue().stream().map(CompareCommand::measurement).filter(inB::contains).count();
            }
        }
        return shared;
    }

    /** A run as measured: two runs of one matrix on two machines share the key, never the start and the results. */
    private static List<String> measurement(StoredRun r) {
        return Arrays.asList(r.runKey, r.startedAt, r.summaryJson);
    }

    private static Set<String> keys(List<StoredRun> runs) {
        return runs.stream().map(r -> r.runKey).collect(Collectors.toSet());
    }

    private boolean hasFilter() {
        return policy != null || particles != null || dataset != null;
    }

    private List<StoredRun> filtered(List<StoredRun> runs) {
        return runs.stream()
                .filter(r -> policy == null || policy.equals(r.policy))
                .filter(r -> particles == null || particles == r.particles)
                .filter(r -> dataset == null || dataset.equals(r.dataset))
                .collect(Collectors.toList());
    }

    /**
     * The runs of configuration {@code spec} among {@code runs}, those of {@code all} the filters keep. When
     * none is left the option at fault is named: {@code option} when {@code all} has no such configuration
     * either, else the filter that leaves it no run.
     */
    private List<StoredRun> choose(List<StoredRun> runs, List<StoredRun> all, String spec, String option, Path file) {
        if (match(runs, spec).isEmpty()) {
            List<StoredRun> unfiltered = match(all, spec);
            if (unfiltered.isEmpty()) {
                return select(all, spec, option, file); // refuses the configuration, naming the option
            }
            throw noRunUnderTheFilters(unfiltered, option + " " + spec, file);
        }
        return select(runs, spec, option, file);
    }

    /** A filter of the runs: its option, the field it tests (singular and plural) and the value asked for. */
    private record Filter(String option, String field, String fields, Object value, Function<StoredRun, Object> of) {
    }

    private List<Filter> filters() {
        List<Filter> out = new ArrayList<>();
        if (policy != null) {
            out.add(new Filter("--policy", "policy", "policies", policy, r -> r.policy));
        }
        if (particles != null) {
            out.add(new Filter("--particles", "particles", "particle counts", particles, r -> r.particles));
        }
        if (dataset != null) {
            out.add(new Filter("--dataset", "dataset", "datasets", dataset, r -> r.dataset));
        }
        return out;
    }

    /**
     * The filter that leaves none of {@code runs}, those of one side ({@code who}) in {@code file}, with the
     * values they have; or the filters given, when each keeps some run but together they keep none.
     */
    private BadUsageException noRunUnderTheFilters(List<StoredRun> runs, String who, Path file) {
        List<Filter> filters = filters();
        for (Filter f : filters) {
            if (runs.stream().noneMatch(r -> f.value().equals(f.of().apply(r)))) {
                TreeSet<String> have = runs.stream().map(r -> String.valueOf(f.of().apply(r)))
                        .collect(Collectors.toCollection(TreeSet::new));
                return new BadUsageException(f.option() + ": no run of " + who + " in " + file + " has " + f.field() + " '"
                        + f.value() + "' (its " + f.fields() + ": " + String.join(", ", have) + ")");
            }
        }
        return new BadUsageException(filters.stream().map(Filter::option).collect(Collectors.joining(", ")) + ": no run of "
                + who + " in " + file + " has these together");
    }

    /**
     * The runs of one configuration: an exact label ({@code temurin-25/g1 / scj}), or a runtime
     * followed by any of a profile, an engine and a memory style, separated by {@code /}
     * ({@code temurin-25/scj}, {@code temurin-25/g1/scj/scoped}), which must leave one configuration.
     * What is not named defaults to the Java SE engine and the preallocated style when the runtime
     * has them, so that {@code temurin-25} is the Java SE engine beside {@code temurin-25/scj}.
     *
     * @throws BadUsageException naming {@code option} when no run or several configurations match
     */
    static List<StoredRun> select(List<StoredRun> runs, String spec, String option, Path file)
            throws BadUsageException {
        List<StoredRun> chosen = match(runs, spec);
        TreeSet<String> configs = chosen.stream().map(StoredRun::config).collect(Collectors.toCollection(TreeSet::new));
        Set<String> measured = chosen.stream().filter(StoredRun::ok).map(StoredRun::config).collect(Collectors.toSet());
        if (configs.size() > 1 && measured.size() == 1) {
            // a configuration of unsupported or failed runs only has nothing to compare: no second candidate
            chosen = chosen.stream().filter(r -> measured.contains(r.config())).toList();
            configs.retainAll(measured);
        }
        if (configs.size() > 1) {
            throw new BadUsageException(option + ": " + spec + " has several configurations in " + file + ", say which: "
                    + String.join(", ", configs));
        }
        if (chosen.isEmpty()) {
            TreeSet<String> known = runs.stream().map(StoredRun::config).collect(Collectors.toCollection(TreeSet::new));
            String runtime = spec.split("\\s*/\\s*")[0].strip();
            boolean runtimeKnown = runs.stream().anyMatch(r -> r.runtime.equals(runtime));
            throw new BadUsageException(option + ": " + (runtimeKnown ? "no configuration " + spec : "unknown runtime '" + spec + "'")
                    + " in " + file + (known.isEmpty() ? " (no runs)" : " (known: " + String.join(", ", known) + ")"));
        }
        return chosen;
    }

    /** The runs {@code spec} names ({@link #select}'s rule), of one configuration or of several. */
    private static List<StoredRun> match(List<StoredRun> runs, String spec) {
        List<StoredRun> exact = runs.stream().filter(r -> r.config().equals(spec)).toList();
        if (!exact.isEmpty()) {
            return exact;
        }
        String[] parts = spec.split("\\s*/\\s*");
        String runtime = parts[0].strip();
        String engine = null;
        String memory = null;
        String profile = null;
        for (int i = 1; i < parts.length; i++) {
            String p = parts[i].strip();
            if (ENGINES.contains(p)) {
                engine = p;
            } else if (MEMORY_STYLES.contains(p)) {
                memory = p;
            } else if (!p.isEmpty()) {
                profile = p;
            }
        }
        final String e = engine;
        final String m = memory;
        final String pr = profile;
        List<StoredRun> byRuntime = runs.stream().filter(r -> r.runtime.equals(runtime))
                .filter(r -> pr == null || pr.equals(r.profile))
                .filter(r -> e == null || e.equals(r.engine))
                .filter(r -> m == null || m.equals(r.memory)).toList();
        if (e == null && byRuntime.stream().anyMatch(r -> "javase".equals(r.engine))) {
            byRuntime = byRuntime.stream().filter(r -> "javase".equals(r.engine)).toList();
        }
        if (m == null && byRuntime.stream().anyMatch(r -> "preallocated".equals(r.memory))) {
            byRuntime = byRuntime.stream().filter(r -> "preallocated".equals(r.memory)).toList();
        }
        return byRuntime;
    }

    /** Engines and memory styles a configuration can name (the rest of a name is a profile). */
    static final List<String> ENGINES = Engines.ALL;
    static final List<String> MEMORY_STYLES = List.of("preallocated", "allocating", "scoped");

    private static Map<String, List<StoredRun>> group(List<StoredRun> runs, boolean withConfig) {
        Map<String, List<StoredRun>> out = new LinkedHashMap<>();
        for (StoredRun r : runs) {
            String key = String.format(Locale.ROOT, "%s  %s  %d particles%s", r.dataset, r.policy, r.particles,
                    withConfig ? "  " + r.config() : "");
            out.computeIfAbsent(key, k -> new ArrayList<>()).add(r);
        }
        return out;
    }

    private void printTable(List<StoredRun> ra, List<StoredRun> rb) {
        String fmt = "%-38s %-30s %-30s %8s  %-20s %s%n";
        out.printf(Locale.ROOT, fmt, "metric", "A", "B", "B/A", "95% CI of B/A", "separation");
        // one table is one setting, so one policy: missCount is named for the jobs it counts under it
        String policy = ra.isEmpty() ? null : ra.get(0).policy;
        for (Metric m : METRICS) {
            double[] xa = values(ra, m);
            double[] xb = values(rb, m);
            Row row = compare(xa, xb);
            String unit = m == Metric.MISS_COUNT ? Metric.missCountJobs(policy) : m.unit;
            out.printf(Locale.ROOT, fmt, m.label + " (" + unit + ")", cell(xa), cell(xb), row.ratio, row.ci, row.verdict);
        }
        int failedA = (int) ra.stream().filter(r -> !r.ok()).count();
        int failedB = (int) rb.stream().filter(r -> !r.ok()).count();
        if (failedA + failedB > 0) {
            out.printf(Locale.ROOT, "runs that did not complete: A %d of %d, B %d of %d%n", failedA, ra.size(), failedB, rb.size());
        }
    }

    /** One line of the table, formatted. */
    record Row(String ratio, String ci, String verdict) {
    }

    /** Ratio, its bootstrap CI and {@link Separation}'s wording, for two samples. */
    static Row compare(double[] xa, double[] xb) {
        if (xa.length == 0 || xb.length == 0) {
            return new Row("-", "-", "no data");
        }
        Separation.Result separation = Separation.of(xa, xb);
        Stats.RatioCi r = separation.ratio();
        String ratio = Double.isFinite(r.ratio()) ? String.format(Locale.ROOT, "%.3f", r.ratio()) : (Stats.mean(xb) == 0 ? "1 (0/0)" : "inf");
        if (Double.isNaN(r.ratio()) && Stats.mean(xa) == 0 && Stats.mean(xb) == 0) {
            ratio = "1 (0/0)";
        }
        String ci = !Double.isNaN(r.low()) && !Double.isNaN(r.high()) ? "[" + bound(r.low()) + ", " + bound(r.high()) + "]" : "-";
        return new Row(ratio, ci, separation.text("A", "B"));
    }

    private static String bound(double v) {
        return Double.isInfinite(v) ? "inf" : String.format(Locale.ROOT, "%.3f", v);
    }

    private static double[] values(List<StoredRun> runs, Metric m) {
        return runs.stream().map(m::of).filter(v -> v != null).mapToDouble(Double::doubleValue).toArray();
    }

    private static String cell(double[] xs) {
        if (xs.length == 0) {
            return "-";
        }
        Stats.Interval ci = Stats.bootstrapMean(xs);
        String bounds = ci.bounded() ? " [" + num(ci.low()) + ", " + num(ci.high()) + "]" : "";
        return num(ci.estimate()) + bounds + " n=" + xs.length;
    }

    private static String num(double v) {
        double a = Math.abs(v);
        return String.format(Locale.ROOT, a >= 100 ? "%.1f" : a >= 1 ? "%.3f" : a == 0 ? "%.0f" : "%.4f", v);
    }
}
