package org.jmclbench.tooling.report;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.Properties;
import java.util.TreeSet;
import java.util.function.Consumer;
import java.util.stream.Collectors;

import org.jmclbench.tooling.cli.Counts;
import org.jmclbench.tooling.runtime.RuntimeKind;
import org.jmclbench.tooling.store.StoredRun;
import org.jmclbench.tooling.store.StoredRuns;

import com.fasterxml.jackson.annotation.JsonIgnore;

/**
 * Everything the report shows, aggregated from the store: one {@link Cell} per
 * (dataset, policy, particles, runtime/profile) with the repetitions' statistics, the
 * merged histograms' spectra and a few series, and the charts built from them once
 * ({@link ChartSpecs}); serialised as the page's inlined JSON (the cells' series reach the page
 * through the charts only).
 */
public final class ReportModel {

    public String schema = "jmclbench-report/1";
    public String generatedAt;
    /** Which jmclbench code made the runs ({@link ConfigurationFacts#codeVersions(List)}). */
    public String codeVersions;
    public String database;
    public int runCount;
    /** When the runs were made: {@code runs started <first> to <last>}, or {@code no runs} (for the evaluation's header). */
    @JsonIgnore
    public String runPeriod;
    public List<String> datasets = new ArrayList<>();
    public List<String> policies = new ArrayList<>();
    /** Per policy of the store, what its missCount counts ({@link Metric#missCountJobs}), for the page's words. */
    public Map<String, String> missCountJobs = new LinkedHashMap<>();
    public List<Integer> particles = new ArrayList<>();
    /** The engines of the runs (javase, scj, native, ...), for the engine filter. */
    public List<String> engines = new ArrayList<>();
    public List<ConfigInfo> configs = new ArrayList<>();
    public List<MachineInfo> machines = new ArrayList<>();
    public List<Cell> cells = new ArrayList<>();
    public Map<String, Playground> playgrounds = new LinkedHashMap<>();
    public Selection defaults;
    /** The page's figures (heading, caption) in page order. */
    public List<ChartSpecs.Figure> figures = ChartSpecs.FIGURES;
    /** Every chart of every setting: the page draws them and the export writes them. */
    public List<ChartSpec> charts = new ArrayList<>();
    /** The static bounds on abort latency, from verify (drawn beside the measured abort latency). */
    @JsonIgnore
    public AbortBounds abortBounds = AbortBounds.NONE;

    /**
     * A runtime/profile as shown in the legend and the tables, with its kind (decided once,
     * {@link RuntimeKind}) and its colour in every chart ({@link Palette}).
     */
    public record ConfigInfo(String id, String runtime, String profile, String engine, String memory, RuntimeKind kind,
                             String color, List<String> versions, List<String> flags, List<String> machines, List<String> facts,
                             Execution execution) {
        /** The C baseline the Java runtimes are compared with. */
        @com.fasterxml.jackson.annotation.JsonProperty("nativeBaseline")
        public boolean nativeBaseline() {
            return kind == RuntimeKind.NATIVE;
        }
    }

    /**
     * A memory area of a configuration over its completed repetitions: the largest size and peak
     * (bytes; for a handler's private memory, the peak of one release), the mean bytes allocated per
     * release, and the releases measured and those that allocated anything, summed over the runs
     * (a preallocated release style shows 0 of N, or a JIT one-off such as 1 of N on HotSpot:
     * rtsj-compat/README.md); null where no run told.
     */
    public record MemoryArea(String name, Long size, Long peakBytes, Double bytesPerRelease, int runs,
                             Long releases, Long allocatingReleases) {
    }

    /** Areas in the order of the memory chart: the heap, then SCJ's from the longest-lived, then the handlers' private ones. */
    static final List<String> AREA_ORDER = List.of("heap", "immortal", "mission");

    /** An area's place in {@link #AREA_ORDER}; the handlers' private areas after those. */
    static int areaRank(String name) {
        int i = AREA_ORDER.indexOf(name);
        return i < 0 ? AREA_ORDER.size() : i;
    }

    /** A machine with the doctor's facts. */
    public record MachineInfo(String id, String hostname, String kernel, String cpu, Integer processors,
                              String virtualization, List<Map<String, String>> checks) {
    }

    /**
     * Mean over repetitions with its 95% percentile-bootstrap interval [low, high] (null when it
     * cannot be made: one repetition), the range, and the per-run values the separation test needs
     * ({@link Separation}; not on the page). A value of +infinity in a repetition (a response-time
     * quantile among dropped jobs) makes the mean and the max +infinity, with no interval.
     */
    public record Agg(int n, Double mean, Double low, Double high, Double min, Double max,
                      @JsonIgnore double[] values) {
        static Agg of(List<Double> values) {
            double[] xs = values.stream().mapToDouble(Double::doubleValue).toArray();
            if (xs.length == 0) {
                return new Agg(0, null, null, null, null, null, xs);
            }
            if (values.contains(Double.POSITIVE_INFINITY)) {
                double min = values.stream().mapToDouble(Double::doubleValue).min().orElseThrow();
                return new Agg(xs.length, Double.POSITIVE_INFINITY, null, null, min, Double.POSITIVE_INFINITY, xs);
            }
            Stats.Interval ci = Stats.bootstrapMean(xs);
            double min = Double.POSITIVE_INFINITY;
            double max = Double.NEGATIVE_INFINITY;
            for (double x : xs) {
                min = Math.min(min, x);
                max = Math.max(max, x);
            }
            return new Agg(xs.length, finite(ci.estimate()), finite(ci.low()), finite(ci.high()), min, max, xs);
        }

        /** The mean and its interval as {@link Stats.Interval} (NaN where null). */
        public Stats.Interval interval() {
            return new Stats.Interval(mean == null ? Double.NaN : mean, low == null ? Double.NaN : low,
                    high == null ? Double.NaN : high);
        }
    }

    /** A run that did not complete: its status and what it said. */
    public record Failure(int repetition, String status, Integer exitCode, String failure, String stderrTail) {
    }

    /** The playground of a dataset (the thesis's unless the dataset's metadata says otherwise). */
    public record Playground(double width, double height, List<double[]> beacons) {
        static Playground thesis() {
            return new Playground(3.0, 2.0, List.of(new double[] {0, 1}, new double[] {3, 0}, new double[] {3, 2}));
        }
    }

    /** What the page shows first. */
    public record Selection(String dataset, String policy, Integer particles) {
    }

    /** One configuration at one setting, over its repetitions. */
    public static final class Cell {
        public String dataset;
        public String policy;
        public int particles;
        public String config;
        /** The runtime and profile of {@link #config} (the profile empty when none). */
        public String runtime;
        public String profile;
        public String engine;
        public String memory;
        /** The load scenario the runs ran under ({@code none}: an idle machine). */
        public String load;
        /** The load as the name shows it (StoredRun#loadCondition): the scenario, with the alloc load's rates when cells differ in them. */
        public String loadCondition;
        /** The run-key settings its runs share (StoredRun#timeScale and the others); null where the store does not tell. */
        public Double timeScale;
        public String workloadArgs;
        public String datasetDigest;
        /** The runtime's version (a runtime name run at two versions is two cells) and the alloc load's rates; null where none or not told. */
        public String runtimeVersion;
        public Integer allocMbPerS;
        public Integer allocLiveMb;
        /**
         * Whether the completed runs' jobs carry their CPU time (summary.json's {@code engine.cpuTime}
         * says {@code used}); without it the attribution cannot name compute or preemption.
         */
        public boolean cpuTime;
        public int runs;
        public int ok;
        public int failed;
        public int timeout;
        public int unsupported;
        public Map<String, Agg> metrics = new LinkedHashMap<>();
        /** [1/(1-p), latency ms, percentile] of every job's task latency, all repetitions merged. */
        @JsonIgnore
        public List<double[]> latencySpectrum = new ArrayList<>();
        /** [1/(1-p), abort latency ms, percentile] of every job an abort took hold of, all repetitions merged (terminate). */
        @JsonIgnore
        public List<double[]> abortSpectrum = new ArrayList<>();
        /** [release jitter ms, cumulative fraction], all repetitions merged. */
        @JsonIgnore
        public List<double[]> jitterCdf = new ArrayList<>();
        /**
         * Per task (predict, update): [response time ms, fraction of the released jobs completed by
         * then], all repetitions merged; a task is absent when its runs stored no response-time histogram.
         */
        @JsonIgnore
        public Map<String, List<double[]>> responseCompletion = new LinkedHashMap<>();
        /** [event index, task latency ms] of the first repetition. */
        @JsonIgnore
        public List<double[]> latencyPredict = new ArrayList<>();
        @JsonIgnore
        public List<double[]> latencyUpdate = new ArrayList<>();
        /** Per repetition (up to five): [time s, deviation xy m]. */
        @JsonIgnore
        public List<List<double[]>> deviation = new ArrayList<>();
        @JsonIgnore
        public List<Integer> deviationRepetitions = new ArrayList<>();
        /** [x, y] estimated and real, of the first repetition. */
        @JsonIgnore
        public List<double[]> trajectory = new ArrayList<>();
        @JsonIgnore
        public List<double[]> real = new ArrayList<>();
        public List<Failure> failures = new ArrayList<>();
        /** Cause kind to the mean over repetitions of {@code run/cause.<kind>/primary} (jobs per run); empty without attribution. */
        public Map<String, Double> causes = new LinkedHashMap<>();
        /** How many of the completed runs carry attribution rows: the runs {@link #causes} is a mean over. */
        @JsonIgnore
        public int attributedRuns;
        /** [start, end] event index of the first repetition's GC/safepoint pauses, and their kind. */
        @JsonIgnore
        public List<double[]> pauses = new ArrayList<>();
        @JsonIgnore
        public List<String> pauseKinds = new ArrayList<>();
        /** The configuration's memory areas (empty when its runs reported none). */
        public List<MemoryArea> memoryAreas = new ArrayList<>();
        /**
         * For misses per run, {@link Separation}'s verdict against each other configuration at the
         * same setting (dataset, policy, particles): A_LOWER when this cell is lower, B_LOWER, NOT_SEPARATED
         * or TOO_FEW; the page's headline names the lowest only together with what it is not separated from.
         */
        public Map<String, String> missSeparation = new LinkedHashMap<>();
        /** Per task (predict, update, all): {released, deadline misses} summed over the completed runs that report them. */
        @JsonIgnore
        public Map<String, long[]> deadlines = new LinkedHashMap<>();
    }

    /**
     * Extra per-cell aggregates (not {@link Metric}s): the warm-up split of the attribution, in ms and
     * jobs per run; the cell also gets {@code WARM_MISS_RATIO} and {@code STEADY_MISS_RATIO} from them.
     */
    static final Map<String, String[]> WARMUP_METRICS = warmupMetrics();

    private static Map<String, String[]> warmupMetrics() {
        Map<String, String[]> m = new LinkedHashMap<>();
        m.put("WARM_P99", new String[] {"all/taskLatencyNs.warm/p99", "1e-6"});
        m.put("STEADY_P99", new String[] {"all/taskLatencyNs.steady/p99", "1e-6"});
        m.put("WARM_MISSES", new String[] {"all/missedOrLate.warm/value", "1"});
        m.put("STEADY_MISSES", new String[] {"all/missedOrLate.steady/value", "1"});
        m.put("WARM_RELEASED", new String[] {"all/released.warm/value", "1"});
        m.put("STEADY_RELEASED", new String[] {"all/released.steady/value", "1"});
        m.put("WARM_RESPONSE_P99", new String[] {"all/responseTimeNs.warm/p99", "1e-6"});
        m.put("STEADY_RESPONSE_P99", new String[] {"all/responseTimeNs.steady/p99", "1e-6"});
        return m;
    }

    /**
     * Each run's jobs missed or late over its jobs released in one window ({@code WARM} or
     * {@code STEADY}); a run that released none there, or did not split its jobs, is no evidence.
     * The windows differ in length (2 s against the rest of the run), so only their ratios compare.
     */
    private static List<Double> windowMissRatios(List<StoredRun> runs, String window) {
        List<Double> ratios = new ArrayList<>();
        for (StoredRun r : runs) {
            Double missed = r.metric(WARMUP_METRICS.get(window + "_MISSES")[0]);
            Double released = r.metric(WARMUP_METRICS.get(window + "_RELEASED")[0]);
            if (missed != null && released != null && released > 0) {
                ratios.add(missed / released);
            }
        }
        return ratios;
    }

    /** Builds the model, reporting progress through {@code progress} (one line a step), without abort bounds. */
    public static ReportModel build(StoredRuns store, Consumer<String> progress) {
        return build(store, AbortBounds.NONE, progress);
    }

    /** Builds the model with verify's static abort bounds, reporting progress through {@code progress}. */
    public static ReportModel build(StoredRuns store, AbortBounds bounds, Consumer<String> progress) {
        ReportModel m = new ReportModel();
        m.abortBounds = bounds;
        m.generatedAt = java.time.Instant.now().truncatedTo(java.time.temporal.ChronoUnit.SECONDS).toString();
        m.database = store.file().getFileName().toString();
        List<StoredRun> runs = store.runs();
        m.runCount = runs.size();
        m.codeVersions = ConfigurationFacts.codeVersions(runs);
        List<String> starts = runs.stream().map(r -> r.startedAt).filter(Objects::nonNull).sorted().toList();
        m.runPeriod = starts.isEmpty() ? "no runs" : "runs started " + starts.get(0) + " to " + starts.get(starts.size() - 1);
        progress.accept("read " + Counts.of(runs.size(), "run"));

        ConfigurationFacts.labelMachines(runs, store.machines());
        Map<String, List<StoredRun>> byCell = new LinkedHashMap<>();
        for (StoredRun r : runs) {
            byCell.computeIfAbsent(r.dataset + "\u0000" + r.policy + "\u0000" + r.particles + "\u0000" + r.configOnMachine(),
                    k -> new ArrayList<>()).add(r);
        }
        m.datasets = runs.stream().map(r -> r.dataset).collect(Collectors.toCollection(TreeSet::new)).stream().toList();
        m.policies = runs.stream().map(r -> r.policy).collect(Collectors.toCollection(TreeSet::new)).stream().toList();
        m.policies.forEach(p -> m.missCountJobs.put(p, Metric.missCountJobs(p)));
        m.particles = runs.stream().map(r -> r.particles).collect(Collectors.toCollection(TreeSet::new)).stream().toList();
        m.engines = runs.stream().map(r -> r.engine).collect(Collectors.toCollection(TreeSet::new)).stream().toList();
        m.configs = ConfigurationFacts.configs(runs);
        m.machines = ConfigurationFacts.machines(store);
        for (String d : m.datasets) {
            m.playgrounds.put(d, playground(store, runs, d));
        }

        int done = 0;
        long start = System.nanoTime();
        long last = start;
        for (List<StoredRun> group : byCell.values()) {
            m.cells.add(cell(store, group));
            done++;
            if (System.nanoTime() - last > 1_000_000_000L || done == byCell.size()) {
                progress.accept("aggregated configurations " + ReportCommand.eta(done, byCell.size(), start));
                last = System.nanoTime();
            }
        }
        CellAggregates.separateMisses(m.cells);
        m.defaults = defaults(m, runs);
        m.charts = ChartSpecs.all(m);
        return m;
    }

    private static Cell cell(StoredRuns store, List<StoredRun> group) {
        StoredRun first = group.get(0);
        Cell c = new Cell();
        c.dataset = first.dataset;
        c.policy = first.policy;
        c.particles = first.particles;
        c.config = first.configOnMachine();
        c.runtime = first.runtime;
        c.profile = first.profile;
        c.engine = first.engine;
        c.memory = first.memory;
        c.load = first.loadScenario();
        c.timeScale = first.timeScale;
        c.workloadArgs = first.workloadArgs;
        c.datasetDigest = first.datasetDigest;
        c.loadCondition = first.loadCondition();
        c.runtimeVersion = first.runtimeVersion;
        c.allocMbPerS = first.allocMbPerS;
        c.allocLiveMb = first.allocLiveMb;
        c.runs = group.size();
        List<StoredRun> ok = new ArrayList<>();
        for (StoredRun r : group) {
            switch (r.status) {
                case "ok" -> ok.add(r);
                case "timeout" -> c.timeout++;
                case "unsupported" -> c.unsupported++;
                default -> c.failed++;
            }
            if (!r.ok()) {
                c.failures.add(new Failure(r.repetition, r.status, r.exitCode, r.failure, tail(r.stderrTail)));
            }
        }
        c.ok = ok.size();
        for (Metric metric : Metric.values()) {
            List<Double> values = new ArrayList<>();
            for (StoredRun r : ok) {
                Double v = metric.of(r);
                if (v != null) {
                    values.add(v);
                }
            }
            c.metrics.put(metric.name(), Agg.of(values));
        }
        for (String task : TaskMetric.TASKS) {
            for (TaskMetric metric : TaskMetric.values()) {
                List<Double> values = new ArrayList<>();
                for (StoredRun r : ok) {
                    Double v = metric.of(r, task);
                    if (v != null) {
                        values.add(v);
                    }
                }
                c.metrics.put(metric.key(task), Agg.of(values));
            }
        }
        for (Map.Entry<String, String[]> e : WARMUP_METRICS.entrySet()) {
            double scale = Double.parseDouble(e.getValue()[1]);
            List<Double> values = new ArrayList<>();
            for (StoredRun r : ok) {
                Double v = r.metric(e.getValue()[0]);
                if (v != null) {
                    values.add(v * scale);
                }
            }
            c.metrics.put(e.getKey(), Agg.of(values));
        }
        for (String window : List.of("WARM", "STEADY")) {
            c.metrics.put(window + "_MISS_RATIO", Agg.of(windowMissRatios(ok, window)));
        }
        c.cpuTime = !ok.isEmpty() && ok.stream().allMatch(r -> r.summary().at("/engine/cpuTime").asText("").startsWith("used"));
        c.causes = CellAggregates.causes(ok);
        c.attributedRuns = (int) ok.stream().filter(CellAggregates::attributed).count();
        c.deadlines = CellAggregates.deadlines(ok);
        c.memoryAreas = CellAggregates.memoryAreas(ok);
        if (ok.isEmpty()) {
            return c;
        }
        CellSeries.read(store, ok, c);
        return c;
    }

    private static Playground playground(StoredRuns store, List<StoredRun> runs, String dataset) {
        for (StoredRun r : runs) {
            if (!dataset.equals(r.dataset) || !r.ok()) {
                continue;
            }
            String path = r.summary().at("/parameters/dataset/path").asText("");
            if (path.isEmpty()) {
                continue;
            }
            Path props = Path.of(path).resolve("dataset.properties");
            if (!props.isAbsolute() && store.file().getParent() != null) {
                props = store.file().toAbsolutePath().getParent().resolve(props);
            }
            if (Files.isRegularFile(props)) {
                try (var in = Files.newBufferedReader(props)) {
                    Properties p = new Properties();
                    p.load(in);
                    double w = Double.parseDouble(p.getProperty("playground.width", "3.0"));
                    double h = Double.parseDouble(p.getProperty("playground.height", "2.0"));
                    List<double[]> beacons = new ArrayList<>();
                    for (String b : p.getProperty("beacons", "0.0,1.0;3.0,0.0;3.0,2.0").split(";")) {
                        String[] xy = b.split(",");
                        beacons.add(new double[] {Double.parseDouble(xy[0].trim()), Double.parseDouble(xy[1].trim())});
                    }
                    return new Playground(w, h, beacons);
                } catch (Exception e) {
                    break; // unreadable metadata: the thesis's playground
                }
            }
            break;
        }
        return Playground.thesis();
    }

    private static Selection defaults(ReportModel m, List<StoredRun> runs) {
        if (runs.isEmpty()) {
            return new Selection(null, null, null);
        }
        Map<String, Long> perDataset = runs.stream().collect(Collectors.groupingBy(r -> r.dataset, java.util.TreeMap::new, Collectors.counting()));
        String dataset = perDataset.entrySet().stream().max(Map.Entry.comparingByValue()).get().getKey();
        String policy = m.policies.contains("skip") ? "skip" : m.policies.get(0);
        List<Integer> ps = runs.stream().filter(r -> r.dataset.equals(dataset) && r.policy.equals(policy))
                .map(r -> r.particles).distinct().sorted().toList();
        Integer particles = ps.isEmpty() ? m.particles.get(0) : ps.get(ps.size() / 2);
        return new Selection(dataset, policy, particles);
    }

    private static String tail(String s) {
        if (s == null) {
            return null;
        }
        return s.length() <= 2000 ? s : s.substring(s.length() - 2000);
    }

    private static Double finite(double v) {
        return Double.isFinite(v) ? v : null;
    }
}
