package org.jmclbench.tooling.store;

import java.math.BigDecimal;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Collection;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.Set;
import java.util.function.Function;
import java.util.stream.Collectors;

import org.jmclbench.tooling.load.LoadScenario;
import org.jmclbench.tooling.load.LoadSettings;
import org.jmclbench.tooling.runner.MatrixDefaults;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.MissingNode;

/** One row of {@code runs} as the report reads it back ({@link StoredRuns}), with its flattened metrics. */
public final class StoredRun {

    private static final ObjectMapper JSON = new ObjectMapper();

    public String runKey;
    public String matrixId;
    public String machineId;
    public String runtime;
    public String runtimeVersion;
    public String profile;
    public String policy;
    public int particles;
    public String dataset;
    public String load;
    /**
     * Settings of the run key the columns above lack (MatrixPlanner.runKey): the replay's time scale,
     * the workload arguments given with {@code --workload-arg} (empty when none) and the digest of the
     * dataset's content; null where the store does not tell (a run of a matrix before they were recorded).
     */
    public Double timeScale;
    public String workloadArgs;
    public String datasetDigest;
    /**
     * The alloc load's rates (MB/s allocated, MB kept live), which the run key holds when the load
     * scenario allocates; null for a scenario that does not, or where the store does not tell.
     */
    public Integer allocMbPerS;
    public Integer allocLiveMb;
    /** javase | scj | native (later hvm); from the column, else the summary, else the runtime (a store before engines). */
    public String engine;
    /** preallocated | allocating | scoped. */
    public String memory;
    /** The jmclbench commit that made the run; null in a store before schema 3, or for a build outside git. */
    public String codeVersion;
    /** The run's memory areas (summary.json memory.areas), in the order the run reported them. */
    public final List<MemoryAreaRow> areas = new ArrayList<>();
    public int repetition;
    public String status;
    public Integer exitCode;
    public String failure;
    public String stderrTail;
    public String startedAt;
    public Double wallS;
    public String runDir;
    public String summaryJson;
    /** {@code task/metric/stat} -> value. */
    public final Map<String, Double> metrics = new HashMap<>();
    /** summary_json parsed on first use; a missing node when absent or invalid. */
    private JsonNode summary;

    /** Set by the report when the store holds several machines: the same runtime on two machines is two configurations. */
    public String machineLabel;
    /** Set by {@link #labelEngines} when the runs have several engines or memory styles. */
    private boolean showEngine;
    private boolean showMemory;
    private boolean showLoad;
    private boolean showTimeScale;
    private boolean showWorkloadArgs;
    private boolean showDatasetDigest;
    private boolean showRuntimeVersion;
    private boolean showAllocRates;

    /**
     * The configuration under test: runtime, and profile when there is one; then, when the runs
     * shown together have several engines or memory styles, the engine and memory style:
     * {@code temurin-25/default / scj scoped}, {@code native / allocating}; and when they ran under
     * several load scenarios, a loaded run's scenario in brackets: {@code temurin-25/default [load cpu]}
     * (a run on an idle machine keeps the plain name). Likewise, before the load, the settings the runs
     * shown together differ in: {@code native [time scale 0.5]} (a run at 1 keeps the plain name),
     * {@code native [--estimate best]} (a run without workload arguments keeps it), and the dataset's
     * digest, {@code native [data 0123abcd]}, when two datasets of one name differ in content; first of
     * them the runtime's version, {@code temurin-17/g1 [17.0.16+8]}, when the runs of one runtime name
     * differ in it; and the alloc load's rates in its bracket, {@code [load alloc 200 MB/s, 64 MB live]},
     * when the allocating runs differ in them. A setting shown that the run's store does not tell reads
     * {@code unknown} ({@code temurin-17/g1 [version unknown]}).
     */
    public String config() {
        String c = profile == null || profile.isEmpty() ? runtime : runtime + "/" + profile;
        List<String> parts = new ArrayList<>();
        if (showEngine && !"native".equals(engine)) {
            parts.add(engine);
        }
        if (showMemory) {
            parts.add(memory);
        }
        String base = (parts.isEmpty() ? c : c + " / " + String.join(" ", parts)) + settingsLabel();
        boolean shown = showLoad || !loadCondition().equals(loadScenario());
        return shown && !"none".equals(loadScenario()) ? base + loadLabel(loadCondition()) : base;
    }

    /**
     * The load as {@link #config()} names it: the scenario, followed by the alloc load's rates when the
     * allocating runs shown together differ in them ({@code alloc 200 MB/s, 64 MB live}).
     */
    public String loadCondition() {
        if (!showAllocRates || !underAllocLoad()) {
            return loadScenario();
        }
        return loadScenario() + " " + (allocMbPerS != null && allocLiveMb != null ? LoadSettings.allocText(allocMbPerS, allocLiveMb)
                : "rates " + UNKNOWN);
    }

    /** Whether the run's load scenario allocates (alloc, mixed): only then has it rates, told or not. */
    public boolean underAllocLoad() {
        return Arrays.stream(LoadScenario.values()).anyMatch(l -> l.alloc() && l.label().equals(loadScenario()));
    }

    /**
     * What {@link #config()} adds for the settings shown; empty for a run at the defaults (time scale 1,
     * no workload arguments); {@link #UNKNOWN} for a setting shown that the store does not tell of it.
     */
    private String settingsLabel() {
        StringBuilder b = new StringBuilder();
        if (showRuntimeVersion) {
            b.append(" [").append(runtimeVersion == null ? "version " + UNKNOWN : runtimeVersion).append(']');
        }
        if (showDatasetDigest) {
            b.append(" [data ").append(datasetDigest == null ? UNKNOWN : datasetDigest.substring(0, Math.min(8, datasetDigest.length())))
                    .append(']');
        }
        if (showTimeScale && (timeScale == null || timeScale != MatrixDefaults.TIME_SCALE)) {
            b.append(" [time scale ").append(timeScale == null ? UNKNOWN : BigDecimal.valueOf(timeScale).stripTrailingZeros().toPlainString())
                    .append(']');
        }
        if (showWorkloadArgs && (workloadArgs == null || !workloadArgs.isEmpty())) {
            b.append(" [").append(workloadArgs == null ? "workload arguments " + UNKNOWN : workloadArgs).append(']');
        }
        return b.toString();
    }

    /**
     * What a label says of a setting the store does not tell for a run, while other runs shown with it
     * tell theirs: the run may or may not share it, so it is pooled with neither (its own group).
     */
    static final String UNKNOWN = "unknown";

    /** The load scenario the run ran under; a store row without one ran on an idle machine ({@code none}). */
    public String loadScenario() {
        return load == null || load.isEmpty() ? "none" : load;
    }

    /** What {@link #config()} appends for a load ({@link #loadCondition()}) when the runs shown together differ in it. */
    public static String loadLabel(String scenario) {
        return " [load " + scenario + "]";
    }

    /** {@link #config()}, with " @host" when the report tells machines apart. */
    public String configOnMachine() {
        return machineLabel == null ? config() : config() + " @" + machineLabel;
    }

    public boolean ok() {
        return "ok".equals(status);
    }

    /** The first of {@code task/metric/stat} keys present, or null. */
    public Double metric(String... keys) {
        for (String k : keys) {
            Double v = metrics.get(k);
            if (v != null) {
                return v;
            }
        }
        return null;
    }

    /**
     * A number of the run: the first of the flattened metrics {@code keys} it has, else the number at
     * {@code pointer} in its summary.json, where {@code "inf"} (a response-time quantile that falls
     * among jobs that never completed) is +infinity; null when neither has one.
     */
    public Double value(String pointer, String... keys) {
        Double v = metric(keys);
        if (v != null) {
            return v;
        }
        JsonNode n = summary().at(pointer);
        if (n.isNumber()) {
            return n.asDouble();
        }
        return n.isTextual() && n.asText().equals("inf") ? Double.POSITIVE_INFINITY : null;
    }

    /** The run's summary.json as a tree (a missing node when there is none or it is not JSON). */
    public JsonNode summary() {
        if (summary == null) {
            try {
                summary = summaryJson == null ? MissingNode.getInstance() : JSON.readTree(summaryJson);
            } catch (Exception e) {
                summary = MissingNode.getInstance();
            }
        }
        return summary;
    }

    /**
     * Marks the runs' labels to show the engine when the JVM runs among them have more than one,
     * and the memory style when they have more than one, so that a store of one engine keeps its
     * short labels ({@code temurin-25/g1}); likewise the load scenario, so that runs on an idle and
     * on a loaded machine are never pooled into one configuration, and each setting of the run key the
     * columns lack ({@link #timeScale}, {@link #workloadArgs}, {@link #datasetDigest}, the alloc load's
     * rates), and the version of a runtime name whose runs ran on more than one (a JVM updated between two
     * matrices). A run whose store does not tell a setting that other runs of its runtime (of its dataset,
     * for the digest) tell differs from them in it: it may not share their value, so it is a group of its
     * own, labelled {@code [version unknown]}, {@code [time scale unknown]} and so on; a runtime none of
     * whose runs tells a setting keeps its name.
     */
    public static void labelEngines(Collection<StoredRun> runs) {
        boolean engines = runs.stream().filter(r -> !"native".equals(r.engine)).map(r -> r.engine).distinct().count() > 1;
        boolean memory = runs.stream().map(r -> r.memory).distinct().count() > 1;
        boolean loads = runs.stream().map(StoredRun::loadScenario).distinct().count() > 1;
        boolean timeScales = differ(runs, r -> r.timeScale);
        boolean workloadArgs = differ(runs, r -> r.workloadArgs);
        // distinct datasets differ in content by nature: only two contents of one name need telling apart
        Set<String> reused = severalOf(runs, r -> r.dataset, r -> r.datasetDigest);
        Set<String> updated = severalOf(runs, r -> r.runtime, r -> r.runtimeVersion);
        // only an allocating run has rates: an idle one's are no unknown rates
        List<StoredRun> allocating = runs.stream().filter(StoredRun::underAllocLoad).toList();
        Function<StoredRun, Object> rates = r -> r.allocMbPerS == null || r.allocLiveMb == null ? null : List.of(r.allocMbPerS, r.allocLiveMb);
        boolean allocRates = differ(allocating, rates);
        Set<String> scaleUntold = partlyTold(runs, r -> r.timeScale);
        Set<String> argsUntold = partlyTold(runs, r -> r.workloadArgs);
        Set<String> ratesUntold = partlyTold(allocating, rates);
        for (StoredRun r : runs) {
            r.showEngine = engines;
            r.showMemory = memory;
            r.showLoad = loads;
            r.showTimeScale = r.timeScale != null ? timeScales : scaleUntold.contains(r.runtime);
            r.showWorkloadArgs = r.workloadArgs != null ? workloadArgs : argsUntold.contains(r.runtime);
            r.showDatasetDigest = reused.contains(r.dataset);
            r.showRuntimeVersion = updated.contains(r.runtime);
            r.showAllocRates = rates.apply(r) != null ? allocRates : ratesUntold.contains(r.runtime);
        }
    }

    /**
     * The names ({@code name}) whose runs have more than one value of {@code setting}, a run that does not
     * tell it ({@code null}) having a value of its own beside a known one ({@link #UNKNOWN}).
     */
    private static Set<String> severalOf(Collection<StoredRun> runs, Function<StoredRun, String> name,
                                         Function<StoredRun, String> setting) {
        return runs.stream().collect(Collectors.groupingBy(name, Collectors.mapping(setting, Collectors.toSet()))).entrySet()
                .stream().filter(e -> e.getValue().size() > 1).map(Map.Entry::getKey).collect(Collectors.toSet());
    }

    /** Whether the runs have more than one known value of {@code setting}. */
    private static boolean differ(Collection<StoredRun> runs, Function<StoredRun, Object> setting) {
        return runs.stream().map(setting).filter(Objects::nonNull).distinct().count() > 1;
    }

    /**
     * The runtimes some of whose runs tell {@code setting} and some do not: those that do not are
     * labelled {@link #UNKNOWN}, apart from the others (a runtime none of whose runs tells it keeps its name).
     */
    private static Set<String> partlyTold(Collection<StoredRun> runs, Function<StoredRun, Object> setting) {
        return runs.stream().collect(Collectors.groupingBy(r -> r.runtime, Collectors.mapping(r -> setting.apply(r) != null,
                Collectors.toSet()))).entrySet().stream().filter(e -> e.getValue().size() > 1).map(Map.Entry::getKey)
                .collect(Collectors.toSet());
    }
}
