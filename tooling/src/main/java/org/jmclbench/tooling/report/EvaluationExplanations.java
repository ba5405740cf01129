package org.jmclbench.tooling.report;

import java.io.IOException;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.function.Function;
import java.util.stream.Collectors;

import com.fasterxml.jackson.databind.JsonNode;

import static org.jmclbench.tooling.report.EvaluationData.*;

/**
 * The evaluation's sections that explain the results (2.6, 2.10-2.13): the memory model, the overrun
 * policies, the collectors, the causes of the misses and what the verification proves. Part of
 * {@link EvaluationDocument}, writing into the same text.
 */
final class EvaluationExplanations extends EvaluationSections {
    EvaluationExplanations(EvaluationSections document) {
        super(document);
    }

    /**
     * The cells of every group (cells of one {@code group} key, in first-seen order) in which
     * {@code varied} takes more than {@code moreThan} values: the groups that compare something.
     */
    private static List<ReportModel.Cell> groupsVarying(List<ReportModel.Cell> cells, Function<ReportModel.Cell, String> group,
            Function<ReportModel.Cell, ?> varied, int moreThan) {
        Map<String, List<ReportModel.Cell>> groups = new LinkedHashMap<>();
        cells.forEach(c -> groups.computeIfAbsent(group.apply(c), k -> new ArrayList<>()).add(c));
        return groups.values().stream().filter(g -> g.stream().map(varied).distinct().count() > moreThan)
                .flatMap(List::stream).toList();
    }

    void memoryModel() throws IOException {
        line("### 2.10 The memory-model experiment (Table 10, Figure 10)");
        line("");
        // One runtime, profile and engine at one count in more than one memory style: a memory style
        // is compared only with its own engine's others, never across engines (the rtsj engine, say,
        // runs on the same heap as javase preallocated and is no memory style of its own).
        Map<String, List<ReportModel.Cell>> byEngine = new LinkedHashMap<>();
        for (ReportModel.Cell c : data.sweep()) {
            if (c.ok > 0 && EvaluationDocument.idle(c)) { // a run beside a load is 2.8's, not a memory style
                byEngine.computeIfAbsent(engineKey(c) + "@" + c.particles, k -> new ArrayList<>()).add(c);
            }
        }
        List<ReportModel.Cell> exp = new ArrayList<>();
        for (List<ReportModel.Cell> group : byEngine.values()) {
            if (group.stream().map(c -> c.memory).distinct().count() > 1) {
                exp.addAll(group);
            }
        }
        if (absent(exp, "The store has no engine that ran more than one memory style on the same runtime at the same "
                + "particle count, so the memory-model experiment is not in it.")) {
            return;
        }
        exp = data.order(exp);
        List<List<String>> rows = new ArrayList<>();
        for (ReportModel.Cell c : exp) {
            String areas = c.memoryAreas.stream().map(EvaluationData::areaText).collect(Collectors.joining("; "));
            rows.add(List.of(c.config, String.valueOf(c.particles), agg(c, Metric.MISS_COUNT, 1), agg(c, Metric.LATENCY_MEAN, 3),
                    agg(c, Metric.LATENCY_P99, 3), areas.isEmpty() ? "not reported" : areas));
        }
        line("Table 10: per runtime and engine, each memory style it ran at the same particle count, policy skip: allocating "
                + "(the garbage-collected heap, temporaries allocated per job) against preallocated (javase: the heap, no "
                + "allocation per job; scj and hvm: immortal and mission memory) against scoped (a private memory per release, "
                + "emptied after it): dropped jobs per run (missCount), task latency (ms), and per memory area its peak use, how "
                + "many releases allocated in it and the bytes allocated per release.");
        line("");
        table(List.of("configuration", "particles", "dropped", "latency mean", "latency p99",
                "memory areas: peak (releases that allocated, allocated per release)"), rows);
        // The figure's count: the one with the most configurations reporting their areas (so HotSpot
        // and the HVM side by side where both ran), the heavier on a tie.
        List<ReportModel.Cell> finalExp = exp;
        int shown = exp.stream().map(c -> c.particles).distinct()
                .max(Comparator.comparingLong((Integer n) -> finalExp.stream()
                        .filter(c -> c.particles == n && !c.memoryAreas.isEmpty()).count()).thenComparing(n -> n))
                .orElseThrow();
        List<ReportModel.Cell> fig = exp.stream().filter(c -> c.particles == shown).toList();
        figure("memory-" + shown, "Figure 10: peak bytes per memory area, " + shown + " particles (log scale).",
                () -> charts.write(ChartSpecs.memory(scope(shown, fig)).withStem("memory-" + shown)));
        styleAgainstPreallocated(fig, shown);
    }

    /** Runtime, profile and engine of a cell: what stays the same while the memory style varies. */
    private String engineKey(ReportModel.Cell c) {
        return data.info(c).runtime() + "/" + data.info(c).profile() + " " + c.engine;
    }

    /**
     * Each memory style against the same runtime's and engine's preallocated style, at the figure's
     * count: what allocating or a scope per release costs that engine.
     */
    private void styleAgainstPreallocated(List<ReportModel.Cell> fig, int n) {
        List<String> bullets = new ArrayList<>();
        List<String> found = new ArrayList<>();
        for (ReportModel.Cell other : fig) {
            ReportModel.Cell pre = fig.stream().filter(c -> "preallocated".equals(c.memory)
                    && engineKey(c).equals(engineKey(other))).findFirst().orElse(null);
            if (pre == null || other == pre || mean(other, Metric.LATENCY_MEAN) == null || mean(pre, Metric.LATENCY_MEAN) == null) {
                continue;
            }
            String meanTest = separate(other, pre, Metric.LATENCY_MEAN).text(other.config, pre.config);
            bullets.add(String.format(Locale.ROOT, "- %s against %s: mean task latency %s against %s ms (%s), p99 %s against %s ms "
                    + "(%s); dropped jobs per run %s against %s.", other.config, pre.config,
                    agg(other, Metric.LATENCY_MEAN, 3), agg(pre, Metric.LATENCY_MEAN, 3), meanTest,
                    agg(other, Metric.LATENCY_P99, 3), agg(pre, Metric.LATENCY_P99, 3),
                    separate(other, pre, Metric.LATENCY_P99).text(other.config, pre.config),
                    agg(other, Metric.MISS_COUNT, 1), agg(pre, Metric.MISS_COUNT, 1)));
            found.add(String.format(Locale.ROOT, "%s %sx (%s)", other.config,
                    num(mean(other, Metric.LATENCY_MEAN) / mean(pre, Metric.LATENCY_MEAN), 2), meanTest));
        }
        if (found.isEmpty()) {
            return;
        }
        line(String.format(Locale.ROOT, "At %d particles, each memory style against the same runtime's and engine's "
                + "preallocated style (Table 10; Mann-Whitney U with the bootstrap interval of the ratio, docs/REPORT.md). A "
                + "style is compared with its own engine only: engines differ in more than their memory. The evaluation runs "
                + "the memory styles in a section of their own ([memory], after [compare], whose runs are the preallocated "
                + "ones): runs are shuffled within a section, not across sections, so the machine's drift between the two "
                + "can make a separated difference of a few percent.", n));
        line("");
        bullets.forEach(this::line);
        line("");
        findings.add(String.format(Locale.ROOT, "Memory model at %d particles, mean task latency against the same engine's "
                + "preallocated style: %s (2.10).", n, String.join("; ", found)));
    }

    void policies() throws IOException {
        line("### 2.6 Overrun policies: skip, terminate, queue (Table 6)");
        line("");
        List<ReportModel.Cell> rowsCells = groupsVarying(data.cells(c -> c.ok > 0), c -> c.config + "@" + c.particles,
                c -> c.policy, 1);
        if (absent(rowsCells, "The store has no configuration that ran more than one policy at the same particle count.")) {
            return;
        }
        List<List<String>> rows = new ArrayList<>();
        for (ReportModel.Cell c : data.order(rowsCells)) {
            rows.add(List.of(c.config, String.valueOf(c.particles), c.policy, EvaluationQuestions.percent(c, "all"),
                    agg(c, Metric.MISS_COUNT, 1), agg(c, Metric.LATE, 1), agg(c, Metric.LATENCY_MEAN, 3), agg(c, Metric.DEVIATION, 3)));
        }
        line("Table 6: per configuration and particle count, each policy: the miss ratio over both tasks, the thesis's "
                + "missCount and the late jobs per run, task latency (ms) and mean localization deviation (m): what a policy "
                + "saves in time it may cost in accuracy.");
        line("");
        table(List.of("configuration", "particles", "policy", "miss ratio", MISS_COUNT_BY_POLICY, "late", "latency mean",
                "deviation"), rows);
        Integer n = data.compareCount();
        List<ReportModel.Cell> at = rowsCells.stream().filter(c -> n != null && c.particles == n).toList();
        if (!at.isEmpty()) {
            figure("accuracy-" + n, "Figure 6: skip, terminate and queue as accuracy against timeliness at " + n + " particles: "
                    + "one point per runtime and policy (circle skip, triangle terminate, square queue), 95% CI both ways.",
                    () -> charts.write(TaskCharts.accuracyVsTimeliness(new ChartSpecs.Scope(model,
                            new ChartSpec.Setting(data.dataset, "every policy", n), at)).withStem("accuracy-" + n)));
            policyTradeOff(at, n);
        }
    }

    /**
     * What the three policies did at the comparison load, per configuration that ran all of them:
     * whether queue kept every deadline with the best accuracy, and terminate's accuracy against
     * skip's, which the thesis found better (section 5).
     */
    private void policyTradeOff(List<ReportModel.Cell> at, int n) {
        Map<String, Map<String, ReportModel.Cell>> byConfig = new LinkedHashMap<>();
        for (ReportModel.Cell c : data.order(at)) {
            byConfig.computeIfAbsent(c.config, k -> new LinkedHashMap<>()).put(c.policy, c);
        }
        int all = 0;
        int queueBest = 0;
        int terminateLower = 0;
        int skipLower = 0;
        List<String> terminate = new ArrayList<>();
        for (Map.Entry<String, Map<String, ReportModel.Cell>> e : byConfig.entrySet()) {
            ReportModel.Cell q = e.getValue().get("queue");
            ReportModel.Cell sk = e.getValue().get("skip");
            ReportModel.Cell t = e.getValue().get("terminate");
            if (q == null || sk == null || t == null || mean(q, Metric.DEVIATION) == null || mean(sk, Metric.DEVIATION) == null
                    || mean(t, Metric.DEVIATION) == null) {
                continue;
            }
            all++;
            // queue counts only where it missed nothing and its deviation is separated below both others'
            Double late = mean(q, Metric.DEADLINE_MISSES);
            if (late != null && late == 0 && separate(q, sk, Metric.DEVIATION).verdict() == Separation.Verdict.A_LOWER
                    && separate(q, t, Metric.DEVIATION).verdict() == Separation.Verdict.A_LOWER) {
                queueBest++;
            }
            Separation.Result ts = separate(t, sk, Metric.DEVIATION);
            terminateLower += ts.verdict() == Separation.Verdict.A_LOWER ? 1 : 0;
            skipLower += ts.verdict() == Separation.Verdict.B_LOWER ? 1 : 0;
            terminate.add(String.format(Locale.ROOT, "%s: terminate %s m against skip %s m (%s)", e.getKey(),
                    agg(t, Metric.DEVIATION, 3), agg(sk, Metric.DEVIATION, 3), ts.text("terminate", "skip")));
        }
        if (all == 0) {
            return;
        }
        line(String.format(Locale.ROOT, "At %d particles queue completed every job by its "
                + "deadline with a mean deviation separated below both skip's and terminate's (Mann-Whitney U with the ratio's "
                + "bootstrap interval) in %d of the %d configurations that ran all three: where the runtime keeps up, dropping "
                + "or aborting work buys no deadline and can cost accuracy. The thesis found terminate more accurate than skip; "
                + "here, mean deviation:", n, queueBest, all));
        line("");
        terminate.forEach(t -> line("- " + t + "."));
        line("");
        findings.add(String.format(Locale.ROOT, "Policies at %d particles: queue kept every deadline with a deviation separated below "
                + "skip's and terminate's (Mann-Whitney U with the ratio's bootstrap interval) in %d of %d configurations; terminate's "
                + "deviation separated below skip's in %d, above it in %d (2.6).", n, queueBest, all, terminateLower, skipLower));
    }

    void collectors() throws IOException {
        line("### 2.11 Garbage collectors on one JVM (Table 11)");
        line("");
        List<ReportModel.Cell> gc = groupsVarying(data.sweep().stream().filter(c -> c.ok > 0 && !data.isNative(c)).toList(),
                c -> data.info(c).runtime() + " " + c.engine + " " + c.memory + "@" + c.particles, c -> data.info(c).profile(), 2);
        if (absent(gc, "The store has no JVM that ran several collectors (profiles) at the same particle count.")) {
            return;
        }
        List<List<String>> rows = new ArrayList<>();
        for (ReportModel.Cell c : data.order(gc)) {
            rows.add(List.of(c.config, String.valueOf(c.particles), agg(c, Metric.MISS_COUNT, 1), agg(c, Metric.LATENCY_P99, 3),
                    agg(c, Metric.LATENCY_MAX, 3), agg(c, Metric.JITTER_P99, 3)));
        }
        line("Table 11: one JVM with each collector (profile), policy skip: dropped jobs per run (missCount), task latency p99 "
                + "and max, release jitter p99 (ms).");
        line("");
        table(List.of("configuration", "particles", "dropped", "latency p99", "latency max", "jitter p99"), rows);
    }

    void attribution() throws IOException {
        line("### 2.12 Why deadlines were missed (Table 12, Figure 12)");
        line("");
        List<ReportModel.Cell> missed = data.sweep().stream().filter(c -> c.ok > 0 && !c.causes.isEmpty()
                && c.causes.values().stream().anyMatch(v -> v > 0)).toList();
        if (absent(missed, "No run in the store has attributed misses or late jobs (either nothing was missed, or the runs "
                + "carry no attribution rows).")) {
            return;
        }
        int count = missed.stream().mapToInt(c -> c.particles).max().orElseThrow();
        List<ReportModel.Cell> at = data.order(missed.stream().filter(c -> c.particles == count).toList());
        // a cause recorded but never a job's primary one is no column and no "0.0" beside the blanks of causes not recorded
        List<String> kinds = at.stream().flatMap(c -> c.causes.entrySet().stream()).filter(e -> e.getValue() > 0)
                .map(Map.Entry::getKey).distinct().sorted().toList();
        List<String> header = new ArrayList<>(List.of("configuration", "runs attributed"));
        header.addAll(kinds);
        List<List<String>> rows = new ArrayList<>();
        for (ReportModel.Cell c : at) {
            List<String> row = new ArrayList<>(List.of(c.config, c.attributedRuns + " of " + c.ok));
            kinds.forEach(k -> row.add(c.causes.getOrDefault(k, 0.0) > 0 ? num(c.causes.get(k), 1) : ""));
            rows.add(row);
        }
        line(String.format(Locale.ROOT, "Table 12: at %d particles (policy skip), the missed or late jobs per run by primary cause, "
                + "from the runtime's own events (JFR, GC log) aligned with the job records (docs/RUNNER.md, \"Why a deadline was "
                + "missed\"); mean over the attributed repetitions (runs attributed: a completed run whose runtime left no evidence the "
                + "harness could read, or more than it keeps, is left out, not counted as missing nothing); blank: no job had that "
                + "primary cause.", count));
        line("");
        table(header, rows);
        figure("causes-skip-" + count, "Figure 12: missed or late jobs per run by primary cause, " + count + " particles.",
                () -> charts.write(ChartSpecs.causes(scope(count, at)).withStem("causes-skip-" + count)));
        line("The largest primary cause per configuration (Table 12):");
        line("");
        Map<String, Integer> dominant = new LinkedHashMap<>();
        for (ReportModel.Cell c : at) {
            Map.Entry<String, Double> top = c.causes.entrySet().stream().max(Map.Entry.comparingByValue()).orElseThrow();
            double total = c.causes.values().stream().mapToDouble(Double::doubleValue).sum();
            line(String.format(Locale.ROOT, "- %s: %s of %s attributed jobs per run were %s.", c.config, num(top.getValue(), 1),
                    num(total, 1), top.getKey()));
            dominant.merge(top.getKey(), 1, Integer::sum);
        }
        line("");
        // from the runs themselves: an engine's runs record CPU time or not by the VM and the version that made them
        List<String> noCpu = at.stream().filter(c -> !c.cpuTime).map(c -> c.engine).distinct().sorted().toList();
        if (!noCpu.isEmpty()) {
            line("The jobs of the " + String.join(", ", noCpu) + " engine" + (noCpu.size() > 1 ? "s" : "") + " carry no CPU time "
                    + "in these runs (their summaries do not say `cpuTime: used`, and the job records say -1: an SCJ VM has no "
                    + "per-thread CPU clock, and the rtsj engine read none before it took the shim's clock), so the attribution "
                    + "cannot name *compute* for them: a job of theirs that ran long shows as the *overlap* of the release it "
                    + "delayed. Compare their rows with the others by their totals, not by cause.");
            line("");
        }
        lightestCauses(missed, count);
        findings.add(String.format(Locale.ROOT, "Why deadlines were missed at %d particles, the largest cause per configuration: %s (2.12).",
                count, dominant.entrySet().stream().map(e -> e.getKey() + " for " + e.getValue() + " of " + at.size())
                        .collect(Collectors.joining(", "))));
    }

    /**
     * The misses at the lightest attributed count, where no job computes for anything near its
     * deadline: under skip they are events dropped because the other task's job held the robot.
     */
    void lightestCauses(List<ReportModel.Cell> missed, int heaviest) {
        int lightest = missed.stream().mapToInt(c -> c.particles).min().orElseThrow();
        if (lightest == heaviest) {
            return;
        }
        Map<String, Double> sum = new java.util.TreeMap<>();
        missed.stream().filter(c -> c.particles == lightest)
                .forEach(c -> c.causes.forEach((k, v) -> sum.merge(k, v, Double::sum)));
        double total = sum.values().stream().mapToDouble(Double::doubleValue).sum();
        // whether C missed at that count: the clause about C must say what its runs did
        boolean cMissed = missed.stream().anyMatch(c -> c.particles == lightest && data.isNative(c));
        line(String.format(Locale.ROOT, "At %d particles, the lightest load with a miss, the attributed jobs per run summed over "
                + "the configurations were %s (%s in all). Under skip a miss is also an event dropped because the other task's "
                + "job held the robot at its release (*overlap*: released while that job, running normally, had not yet ended), "
                + "so a light load is not free of misses%s.", lightest,
                sum.entrySet().stream().map(e -> e.getKey() + " " + num(e.getValue(), 1)).collect(Collectors.joining(", ")),
                num(total, 1), cMissed ? ", on C either" : "; C missed none there"));
        line("");
    }

    void verification() throws IOException {
        line("### 2.13 What the verification proves (Table 13)");
        line("");
        if (verification == null) {
            line("**No data.** `" + verificationFile + "` does not exist: the model checking (`verification/`, Java PathFinder) "
                    + "was not run before this document was written, so no property is claimed here.");
            line("");
            findings.add("Verification: no results file (2.13).");
            return;
        }
        // The format ./jmclbench verify writes (verification/VerifyMain): schema 1, one row per check.
        List<List<String>> rows = new ArrayList<>();
        long missionStates = 0;
        int properties = 0;
        int held = 0;
        long rtsjStates = 0;
        int rtsjChecks = 0;
        int rtsjHeld = 0;
        int seeded = 0;
        int caught = 0;
        for (JsonNode c : verification.path("checks")) {
            boolean isSeeded = c.path("seeded").asBoolean();
            boolean passed = c.path("passed").asBoolean();
            boolean mission = c.path("catalog").asText().equals("mission");
            boolean rtsj = c.path("catalog").asText().equals("rtsj");
            String role = isSeeded ? "seeded bug" : mission ? "mission" : rtsj ? "rtsj engine" : "toy program";
            if (isSeeded) {
                seeded++;
                caught += passed ? 1 : 0;
            } else if (mission) {
                properties++;
                held += passed ? 1 : 0;
                missionStates += c.path("states").asLong(0);
            } else if (rtsj) {
                rtsjChecks++;
                rtsjHeld += passed ? 1 : 0;
                rtsjStates += c.path("states").asLong(0);
            }
            String scope = c.path("kind").asText().equals("static") ? "all bytecode of the release classes"
                    : first(c, "scope");
            rows.add(List.of(c.path("id").asText(), role, first(c, "property"), first(c, "policy"), scope,
                    first(c, "verdict"), first(c, "states").isEmpty() ? "-" : first(c, "states"), first(c, "seconds")));
        }
        line("Table 13: the checks of `./jmclbench verify` (from `" + verificationFile.getFileName() + "`, finished "
                + first(verification, "finished") + "). *mission*: a property of the real scj-mission on rtsj-compat "
                + "(Java PathFinder on the inputs in *scope*, or ASM on the bytecode); *rtsj engine*: the same for the "
                + "RTSJ engine's replay (woven, on rtsj-compat's RTSJ layer); *seeded bug*: a mutant the "
                + "same check must report (a check that passes is one that caught it); *toy program*: the properties "
                + "on a small SCJ-like program, where every property has its seeded bug.");
        line("");
        table(List.of("check", "role", "property", "policy", "scope", "verdict", "states", "s"), rows);
        String rtsjHeldOver = rtsjChecks == 0 ? ""
                : String.format(Locale.ROOT, "; on the rtsj engine %d of %d checks hold, over %d states", rtsjHeld,
                        rtsjChecks, rtsjStates);
        line(String.format(Locale.ROOT, "On the real mission %d of %d checks hold, over %d states%s; %d of %d seeded bugs "
                + "were caught (Table 13). Model checking covers the tiny inputs in its scope column, not the "
                + "benchmark's datasets.", held, properties, missionStates, rtsjHeldOver, caught, seeded));
        line("");
        findings.add(String.format(Locale.ROOT, "Verification: %d of %d mission checks hold over %d states%s; %d of %d "
                + "seeded bugs caught (2.13).", held, properties, missionStates, rtsjChecks == 0 ? ""
                        : String.format(Locale.ROOT, " and %d of %d rtsj engine checks over %d states", rtsjHeld,
                                rtsjChecks, rtsjStates), caught, seeded));
    }
}
