package org.jmclbench.tooling.report;

import java.io.IOException;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Objects;

import org.jmclbench.tooling.cli.Counts;
import org.jmclbench.tooling.store.StoredRun;

import static org.jmclbench.tooling.report.EvaluationData.*;

/**
 * The evaluation's sections that answer the real-time question per task and the thesis's open
 * questions: deadline accounting and response time at the comparison load, abort latency under
 * terminate, generic vs real-time scheduling, an idle vs a loaded machine, and steady state vs warm-up. Part of
 * {@link EvaluationDocument}, writing into the same text.
 */
final class EvaluationQuestions extends EvaluationSections {

    /** 2.7's pairs of a runtime's default and its noidle profile, which 2.8 reads to explain a load that speeds jobs up. */
    private final List<ReportModel.Cell[]> awakePairs = new ArrayList<>();

    EvaluationQuestions(EvaluationSections document) {
        super(document);
    }

    /** Per configuration and policy at the comparison load: each task's miss ratio and response time over released jobs. */
    void deadlineAccounting() throws IOException {
        line("### 2.2 Deadline accounting per task (Table 2)");
        line("");
        Integer n = data.compareCount();
        List<ReportModel.Cell> at = n == null ? List.of() : data.order(data.cells(c -> c.particles == n && c.ok > 0 && EvaluationDocument.idle(c)));
        if (absent(at, "No completed run is in the store.")) {
            return;
        }
        line(String.format(Locale.ROOT, "Table 2: at %d particles (the load with the most repetitions), per configuration and "
                + "policy: each task's miss ratio (late + dropped + aborted over released, pooled over the repetitions, "
                + "with its 95%% Wilson interval) and its response time p99 over every released job (∞ where a dropped or aborted job falls in the "
                + "top 1%%: such a run did not complete 99%% of its jobs, however fast the others were).", n));
        line("");
        List<List<String>> rows = new ArrayList<>();
        for (ReportModel.Cell c : at) {
            rows.add(List.of(c.config, c.policy, String.valueOf(c.ok), percent(c, "predict"), percent(c, "update"),
                    response(c, "predict"), response(c, "update"), agg(c, Metric.MISS_COUNT, 1)));
        }
        table(List.of("configuration", "policy", "runs", "predict miss ratio", "update miss ratio", "predict response p99 (ms)",
                "update response p99 (ms)", MISS_COUNT_BY_POLICY), rows);
        for (String policy : List.of("skip", "queue")) {
            List<ReportModel.Cell> cs = at.stream().filter(c -> c.policy.equals(policy)).toList();
            if (cs.isEmpty()) {
                continue;
            }
            for (String task : List.of("predict", "update")) {
                String stem = "completion-" + task + "-" + policy + "-" + n;
                figure(stem, String.format(Locale.ROOT, "Figure 2%s: %s, policy %s, %d particles: the fraction of released jobs "
                                + "completed within a response time (every repetition merged); a curve that ends below 1 dropped or "
                                + "aborted jobs.", task.equals("predict") ? (policy.equals("skip") ? "a" : "c") : (policy.equals("skip") ? "b" : "d"),
                        task, policy, n),
                        () -> charts.write(TaskCharts.responseCompletion(scope(policy, n, cs), task).withStem(stem)));
            }
        }
        findings.add(String.format(Locale.ROOT, "Per-task deadline accounting at %d particles: Table 2 (2.2).", n));
    }

    /**
     * The thesis's section 5.3: the same runtime under the default scheduler and under SCHED_FIFO
     * pinned to one CPU; beside it, where the store has it, the CPUs kept out of deep idle states
     * ({@code noidle}), which separates the machine's wake-up from the runtime's release.
     */
    void scheduling() throws IOException {
        line("### 2.7 Generic vs real-time scheduling (Table 7)");
        line("");
        List<ReportModel.Cell> fifo = data.cells(c -> c.ok > 0 && profileHas(c, "fifo"));
        List<ReportModel.Cell> noidle = data.cells(c -> c.ok > 0 && EvaluationDocument.idle(c) && profileHas(c, "noidle")
                && !profileHas(c, "fifo"));
        if (absent(fifo.isEmpty() ? noidle : fifo, "The store has no run with a `fifo` profile, so generic and real-time "
                + "scheduling are not compared here.")) {
            return;
        }
        List<List<String>> rows = new ArrayList<>();
        List<ReportModel.Cell[]> pairs = new ArrayList<>();
        for (ReportModel.Cell f : data.order(fifo)) {
            ReportModel.ConfigInfo fi = data.info(f);
            ReportModel.Cell plain = defaultOf(f);
            if (plain == null) {
                continue;
            }
            addRow(rows, plain);
            addRow(rows, f);
            pairs.add(new ReportModel.Cell[] {plain, f});
            line(pairSentence(plain, f, Metric.JITTER_P99, "release jitter p99"));
            line("");
            Execution fe = fi.execution();
            if (fe != null && fe.prioritiesIgnored() && fi.profile().contains("pinned")) {
                line(pinnedParagraph(plain, f, fi));
                line("");
            }
        }
        for (ReportModel.Cell n : data.order(noidle)) {
            ReportModel.Cell plain = defaultOf(n);
            if (plain == null) {
                continue;
            }
            if (awakePairs.isEmpty()) {
                line("An idle CPU may sleep in a deep state between jobs, and a job released to it waits for it to wake (on a "
                        + "VM the host may also run it slower once awake). Under `noidle` the runner holds /dev/cpu_dma_latency "
                        + "at 0 for the run, as cyclictest does, so each pair below shows how much of the default's release "
                        + "jitter and task latency is the machine's power management rather than the runtime's.");
                line("");
            }
            addRow(rows, plain);
            addRow(rows, n);
            awakePairs.add(new ReportModel.Cell[] {plain, n});
            line(pairSentence(plain, n, Metric.JITTER_P99, "release jitter p99"));
            line("");
            line(pairSentence(plain, n, Metric.LATENCY_P99, "task latency p99"));
            line("");
        }
        line("Table 7: each runtime under its default profile and under `fifo` (SCHED_FIFO priority 80) with `pinned` where "
                + "given" + (awakePairs.isEmpty() ? "" : ", and with its CPUs kept out of deep idle states (`noidle`)")
                + "; scheduling as the runs recorded it.");
        line("");
        table(List.of("configuration", "particles", "policy", "runs", "miss ratio", "jitter p99 (ms)", "latency p99 (ms)", "scheduling"), rows);
        if (!pairs.isEmpty()) {
            findings.add("Generic vs real-time scheduling, each fifo profile against its runtime's default (the pairs of Table 7): "
                    + separatedPairs(pairs, Metric.JITTER_P99, "release jitter p99") + " (2.7).");
        }
        if (!awakePairs.isEmpty()) {
            findings.add("CPU idle states, each noidle profile against its runtime's default (Table 7): "
                    + separatedPairs(awakePairs, Metric.JITTER_P99, "release jitter p99") + "; "
                    + separatedPairs(awakePairs, Metric.LATENCY_P99, "task latency p99") + " (2.7).");
        }
        List<ReportModel.Cell> variants = new ArrayList<>(fifo);
        variants.addAll(noidle);
        ReportModel.Cell first = variants.get(0);
        List<ReportModel.Cell> compared = data.cells(c -> c.ok > 0 && c.particles == first.particles && c.policy.equals(first.policy)
                && EvaluationDocument.idle(c) && variants.stream().anyMatch(f -> data.info(f).runtime().equals(data.info(c).runtime())
                || data.isNative(c)));
        // the caption names the profiles the figure draws (a store may have fifo without pinned, or neither beside default)
        List<String> profiles = compared.stream().map(c -> data.info(c).profile()).map(p -> p == null || p.isEmpty() ? "default" : p)
                .distinct().sorted().toList();
        figure("scheduling", String.format(Locale.ROOT, "Figure 7: release jitter p99 per runtime under each of its profiles (%s), "
                + "%d particles, policy %s (mean [95%% CI], the interval cut at zero).", String.join(", ", profiles), first.particles,
                first.policy), () -> charts.write(TaskCharts.conditions(scope(first.policy, first.particles, compared),
                "scheduling", "Generic vs real-time scheduling", Metric.JITTER_P99, c -> data.info(c).profile()).withStem("scheduling")));
    }

    /** Whether the cell's profile has the component {@code id} ({@code fifo} in {@code fifo+pinned}). */
    private boolean profileHas(ReportModel.Cell c, String id) {
        String p = data.info(c).profile();
        return p != null && java.util.Arrays.asList(p.split("\\+")).contains(id);
    }

    /** The same configuration as {@code c} under its runtime's default profile, idle, or null. */
    private ReportModel.Cell defaultOf(ReportModel.Cell c) {
        ReportModel.ConfigInfo ci = data.info(c);
        return data.cells(d -> d.ok > 0 && d.particles == c.particles && d.policy.equals(c.policy)
                && Objects.equals(d.engine, c.engine) && Objects.equals(d.memory, c.memory) && EvaluationDocument.idle(d)
                && data.info(d).runtime().equals(ci.runtime()) && isDefault(data.info(d).profile())).stream().findFirst().orElse(null);
    }

    private static boolean isDefault(String profile) {
        return profile == null || profile.isEmpty() || profile.equals("default");
    }

    /** Table 7's row of {@code c}, once (a default is the base of its fifo and its noidle pair). */
    private void addRow(List<List<String>> rows, ReportModel.Cell c) {
        if (rows.stream().anyMatch(r -> r.get(0).equals(c.config) && r.get(1).equals(String.valueOf(c.particles))
                && r.get(2).equals(c.policy))) {
            return;
        }
        rows.add(List.of(c.config, String.valueOf(c.particles), c.policy, String.valueOf(c.ok), percent(c, "all"),
                agg(c, Metric.JITTER_P99, 3), agg(c, Metric.LATENCY_P99, 3), data.info(c).execution() == null ? "?"
                        : data.info(c).execution().scheduling() + ", priorities " + data.info(c).execution().priorities()));
    }

    /**
     * What one SCHED_FIFO priority for every thread on one CPU does to a release, for a pinned FIFO
     * cell {@code f} and its runtime's default {@code plain}: each effect claimed only where the
     * test separates the two (docs/REPORT.md), the effect on dropped jobs only under skip.
     */
    private String pinnedParagraph(ReportModel.Cell plain, ReportModel.Cell f, ReportModel.ConfigInfo fi) {
        String profile = fi.profile();
        StringBuilder t = new StringBuilder(String.format(Locale.ROOT, "At %d particles, policy %s, under %s every thread of %s "
                + "runs at the one SCHED_FIFO priority (its thread priorities are not applied) on one CPU, and a FIFO thread runs "
                + "until it blocks: the dispatcher that releases an event waits for the running job to end. ", f.particles, f.policy,
                profile, fi.runtime()));
        Separation.Result jitter = separate(f, plain, Metric.JITTER_P99);
        boolean later = jitter.verdict() == Separation.Verdict.B_LOWER;
        t.append(String.format(Locale.ROOT, "Release jitter p99 %s against %s ms: %s", agg(f, Metric.JITTER_P99, 3),
                agg(plain, Metric.JITTER_P99, 3), later ? "the release is later under " + profile + " (" + jitter.text(f.config, plain.config) + ")."
                        : "the data do not show a later release (" + jitter.text(f.config, plain.config) + ")."));
        if (!f.policy.equals("skip")) {
            return t.toString();
        }
        // under skip, an event released while the robot is busy is dropped: a later release can find it free
        Separation.Result dropped = separate(f, plain, Metric.MISS_COUNT);
        t.append(String.format(Locale.ROOT, " Skip drops an event released while the robot is busy; dropped jobs per run %s against "
                + "%s (miss ratio %s against %s): ", agg(f, Metric.MISS_COUNT, 1), agg(plain, Metric.MISS_COUNT, 1), percent(f, "all"),
                percent(plain, "all")));
        if (dropped.verdict() == Separation.Verdict.A_LOWER) {
            t.append(later ? "fewer dropped jobs here (" + dropped.text(f.config, plain.config) + ") come from later releases, "
                    + "not from a faster runtime."
                    : "fewer dropped jobs here (" + dropped.text(f.config, plain.config) + "), with no later release to explain them.");
        } else {
            t.append("the data do not show fewer dropped jobs under " + profile + " (" + dropped.text(f.config, plain.config)
                    + "), so no effect on them is claimed.");
        }
        return t.toString();
    }

    /**
     * The termination policies' measured side: per configuration under terminate at the comparison
     * load, the aborts and the abort latency, and its percentile spectrum.
     */
    void termination() throws IOException {
        line("### 2.6b Termination: how long an abort takes (Table 6b, Figure 6b)");
        line("");
        Integer n = data.compareCount();
        List<ReportModel.Cell> at = n == null ? List.of() : data.order(data.cells(c -> c.particles == n && c.ok > 0
                && c.policy.equals("terminate") && EvaluationDocument.idle(c)));
        if (absent(at, "The store has no run under terminate at the comparison load, so abort latency is not reported.")) {
            return;
        }
        List<List<String>> rows = new ArrayList<>();
        boolean anyOver = false;
        // runs that recorded when each job saw its abort (seen_ns) split the latency; older ones do not
        boolean split = at.stream().anyMatch(c -> largest(c, TaskMetric.ABORT_NOTICE_MAX) != null);
        for (ReportModel.Cell c : at) {
            AbortBounds.Bound b = data.model.abortBounds.of(c, data.model);
            Double ms = b == null ? null : b.millis(c);
            String within;
            if (split) {
                within = withinBound(c, ms, TaskMetric.ABORT_NOTICE_P50, TaskMetric.ABORT_NOTICE_P99, TaskMetric.ABORT_NOTICE_MAX);
            } else {
                within = withinBound(c, ms, TaskMetric.ABORT_MAX);
            }
            anyOver |= within.contains("no");
            List<String> row = new ArrayList<>(List.of(c.config, String.valueOf(c.ok), agg(c, TaskMetric.ABORTED.key("all"), 1),
                    agg(c, TaskMetric.ABORT_P50.key("all"), ABORT_DECIMALS), agg(c, TaskMetric.ABORT_P99.key("all"), ABORT_DECIMALS),
                    agg(c, TaskMetric.ABORT_MAX.key("all"), ABORT_DECIMALS)));
            if (split) {
                row.add(agg(c, TaskMetric.ABORT_NOTICE_P50.key("all"), ABORT_DECIMALS));
                row.add(agg(c, TaskMetric.ABORT_NOTICE_P99.key("all"), ABORT_DECIMALS));
                row.add(agg(c, TaskMetric.ABORT_NOTICE_MAX.key("all"), ABORT_DECIMALS));
                row.add(agg(c, TaskMetric.ABORT_STOP_MAX.key("all"), ABORT_DECIMALS));
            }
            row.add(ms == null ? "-" : b.span() + ": " + num(ms, ABORT_DECIMALS) + " ms");
            row.add(within);
            rows.add(row);
        }
        line(String.format(Locale.ROOT, "Table 6b: under terminate at %d particles, per configuration: the jobs aborted per run and "
                + "the abort latency, from the abort request (the gate's request, or the AIE fired at the job) to the aborted job's "
                + "end (ms; mean over repetitions of each run's percentile, with its 95%% bootstrap interval). A cooperative job "
                + "ends at its next poll (every 64 particle steps); the RTSJ thesis design defers the AIE inside the robot's "
                + "monitor, so its job runs to its end and completes: none is counted aborted, and its abort latency is the "
                + "remaining time of the job a request was made to (abortsCompleted in summary.json). The static bound is "
                + "`./jmclbench verify`'s: the longest gap between two abort points in the job's bytecode (particle steps; the whole job where nothing bounds it) times the costliest "
                + "particle step of these runs (the slowest job of either task over its particles), in ms; the C baseline has no "
                + "bytecode to analyse. The last column: whether the largest " + (split ? "p50, p99 and max of noticing"
                : "abort latency") + " of any run is within it (where not, that largest value, ms: a mean under the bound "
                + "can hold a run over it). n/a: no run of the configuration recorded the value.", n));
        line("");
        if (split) {
            line("Noticing runs from the request to the poll (or delivery point) that saw it, stopping from there to the "
                    + "job's end (`seen_ns` in the job files; n/a where no job saw its abort: the RTSJ thesis design, whose job "
                    + "never sees its AIE, and runs recorded before the column). The static bound bounds noticing only.");
            line("");
            table(List.of("configuration", "runs", "aborted per run", "abort latency p50", "abort latency p99", "abort latency max",
                    "noticed p50", "noticed p99", "noticed max", "stopping max", "static bound", "noticing within it (p50 / p99 / max)"),
                    rows);
        } else {
            table(List.of("configuration", "runs", "aborted per run", "abort latency p50", "abort latency p99", "abort latency max",
                    "static bound", "max within it"), rows);
        }
        if (anyOver) {
            line("The bound counts the job's own computing after a request. A measured latency also holds what is not the "
                    + "job's computing: the time until the job's thread runs its next instruction (the request comes from another "
                    + "thread; the job's thread may be preempted, or interrupted by the machine: timer ticks, the hypervisor, the "
                    + "interrupt that wakes the next job's thread on its CPU), and the delivery itself (a poll's return, or the AIE "
                    + "thrown and caught, a rarely taken path that a JIT may first run in its interpreter). The bound does not "
                    + "cover these: it needs the platform's scheduling and delivery costs, which no bytecode analysis gives.");
            line("");
        }
        ChartSpec spectrum = ChartSpecs.abortLatency(scope("terminate", n, at));
        if (spectrum == null) {
            line("No abort took hold in these runs (every job ended before a later release asked it to), so there is no spectrum.");
            line("");
            return;
        }
        figure("abort-latency-" + n, "Figure 6b: abort latency by percentile under terminate, " + n + " particles (every job an "
                + "abort took hold of, aborted or, as in the RTSJ thesis design, run to its end, every repetition merged; log scales).", () -> charts.write(spectrum.withStem("abort-latency-" + n)));
    }

    /**
     * Decimals of a ms in the abort-latency table: its values are microseconds, and three decimals wrote a
     * stopping of 0.3 us as 0.000 and 2.4 against 2.6 us both as 0.002; four keep a tenth of a microsecond.
     */
    static final int ABORT_DECIMALS = 4;

    /**
     * For each metric, whether its largest value over the cell's runs is within the bound of
     * {@code ms}: "yes" or "no", joined by " / "; "-" without a bound or without the metrics.
     */
    private static String withinBound(ReportModel.Cell c, Double ms, TaskMetric... metrics) {
        List<String> verdicts = new ArrayList<>();
        for (TaskMetric m : metrics) {
            Double max = largest(c, m);
            if (ms == null || max == null) {
                return "-";
            }
            verdicts.add(max <= ms ? "yes" : "no (" + num(max, ABORT_DECIMALS) + ")");
        }
        return String.join(" / ", verdicts);
    }

    /** The largest value of {@code metric} (task all) over the cell's runs, or null. */
    private static Double largest(ReportModel.Cell c, TaskMetric metric) {
        ReportModel.Agg a = c.metrics.get(metric.key("all"));
        return a == null ? null : a.max();
    }

    /** An idle machine against the same runs beside a CPU or allocation load (the thesis's further work). */
    void load() throws IOException {
        line("### 2.8 An idle vs a loaded machine (Table 8)");
        line("");
        List<ReportModel.Cell> loaded = data.cells(c -> c.ok > 0 && !EvaluationDocument.idle(c));
        if (absent(loaded, "The store has no run under a load scenario, so an idle and a loaded machine are not compared here.")) {
            return;
        }
        List<List<String>> rows = new ArrayList<>();
        List<ReportModel.Cell[]> pairs = new ArrayList<>();
        List<String> bases = data.order(loaded.stream().map(c -> c.config.replace(StoredRun.loadLabel(c.loadCondition), "")).distinct().toList());
        for (String base : bases) {
            for (ReportModel.Cell l : data.order(loaded.stream().filter(c -> c.config.equals(base + StoredRun.loadLabel(c.loadCondition))).toList())) {
                ReportModel.Cell idle = data.cells(c -> c.ok > 0 && c.config.equals(base) && c.particles == l.particles
                        && c.policy.equals(l.policy)).stream().findFirst().orElse(null);
                if (idle != null && rows.stream().noneMatch(r -> r.get(0).equals(idle.config) && r.get(1).equals(String.valueOf(idle.particles)))) {
                    rows.add(loadRow(idle));
                }
                rows.add(loadRow(l));
                if (idle != null) {
                    pairs.add(new ReportModel.Cell[] {idle, l});
                    // a load takes the CPU from the thread that releases as much as from the job: both are compared
                    line(pairSentence(idle, l, Metric.LATENCY_P99, "task latency p99"));
                    line("");
                    line(pairSentence(idle, l, Metric.JITTER_P99, "release jitter p99"));
                    line("");
                }
            }
        }
        for (ReportModel.Cell[] p : pairs) {
            if (lowerUnderBoth(p, awakePairs.stream().filter(a -> sameCell(a[0], p[0])).findFirst().orElse(null))) {
                line(p[1].config + ": task latency p99 is separated lower beside the load, as it is under noidle on the idle "
                        + "machine (2.7). A busy machine keeps its CPUs out of deep idle states as noidle does; on the idle "
                        + "machine a job runs on a CPU that has just woken, and takes longer there.");
                line("");
            }
        }
        line("Table 8: the same configuration idle and beside a load scenario (docs/RUNNER.md: cpu keeps every CPU busy, "
                + "alloc allocates in another JVM).");
        line("");
        table(List.of("configuration", "particles", "policy", "runs", "miss ratio", "latency p99 (ms)", "jitter p99 (ms)"), rows);
        if (!pairs.isEmpty()) {
            findings.add("An idle vs a loaded machine, each configuration beside a load against it idle (the pairs of Table 8): "
                    + separatedPairs(pairs, Metric.JITTER_P99, "release jitter p99") + "; "
                    + separatedPairs(pairs, Metric.LATENCY_P99, "task latency p99") + " (2.8).");
        }
        ReportModel.Cell first = loaded.get(0);
        List<ReportModel.Cell> compared = data.cells(c -> c.ok > 0 && c.particles == first.particles && c.policy.equals(first.policy)
                && bases.contains(c.config.replace(StoredRun.loadLabel(c.loadCondition), "")));
        figure("load", "Figure 8: task latency p99 on an idle machine and beside each load scenario, per configuration (mean "
                + "[95% CI], the interval cut at zero).", () -> charts.write(TaskCharts.conditions(scope(first.policy, first.particles, compared), "load",
                "Idle vs loaded machine", Metric.LATENCY_P99, c -> c.loadCondition).withStem("load")));
    }

    /** Whether the test puts task latency p99 lower for the variant of {@code loaded} and of {@code awake} (null: no noidle pair). */
    private boolean lowerUnderBoth(ReportModel.Cell[] loaded, ReportModel.Cell[] awake) {
        return awake != null && separate(loaded[0], loaded[1], Metric.LATENCY_P99).verdict() == Separation.Verdict.B_LOWER
                && separate(awake[0], awake[1], Metric.LATENCY_P99).verdict() == Separation.Verdict.B_LOWER;
    }

    private static boolean sameCell(ReportModel.Cell a, ReportModel.Cell b) {
        return a.config.equals(b.config) && a.particles == b.particles && a.policy.equals(b.policy);
    }

    private static List<String> loadRow(ReportModel.Cell c) {
        return List.of(c.config, String.valueOf(c.particles), c.policy, String.valueOf(c.ok), percent(c, "all"),
                agg(c, Metric.LATENCY_P99, 3), agg(c, Metric.JITTER_P99, 3));
    }

    /** Steady state: a long replay, its first seconds (warm-up) apart from the rest. */
    void steadyState() {
        line("### 2.9 Steady state and warm-up (Table 9)");
        line("");
        List<ReportModel.Cell> cells = data.order(data.model.cells.stream().filter(c -> c.ok > 0 && !c.dataset.equals(data.dataset)
                && c.metrics.containsKey("STEADY_RESPONSE_P99") && c.metrics.get("STEADY_RESPONSE_P99").mean() != null).toList());
        if (absent(cells, "The store has no run of a longer replay with its warm-up split recorded, so steady state is not reported apart.")) {
            return;
        }
        List<List<String>> rows = new ArrayList<>();
        for (ReportModel.Cell c : cells) {
            rows.add(List.of(c.config, c.dataset, String.valueOf(c.particles), String.valueOf(c.ok), agg(c, "WARM_RESPONSE_P99", 3),
                    agg(c, "STEADY_RESPONSE_P99", 3), windowMisses(c, "WARM"), windowMisses(c, "STEADY")));
        }
        line("Table 9: the response time p99 (completed jobs, ms, mean over repetitions) and the miss ratio (jobs missed or "
                + "late over jobs released, pooled over the repetitions, with its 95% Wilson interval; in brackets the jobs per "
                + "run) in the warm-up window (jobs released in the run's first 2 s) and after it. The windows differ in "
                + "length, so compare their ratios, not their counts.");
        line("");
        table(List.of("configuration", "dataset", "particles", "runs", "warm-up response p99", "steady response p99",
                "warm-up miss ratio", "steady miss ratio"), rows);
    }

    /** The cells of one policy and particle count as a figure's scope. */
    private ChartSpecs.Scope scope(String policy, int particles, List<ReportModel.Cell> cells) {
        return new ChartSpecs.Scope(model, new ChartSpec.Setting(data.dataset, policy, particles), cells);
    }

    /** A task's miss ratio, pooled over the repetitions, as a percentage with its 95% Wilson interval. */
    static String percent(ReportModel.Cell c, String task) {
        return percent(EvaluationData.missRatio(c, task));
    }

    private static String percent(Stats.Interval i) {
        if (Double.isNaN(i.estimate())) {
            return "n/a";
        }
        return new Stats.Interval(100 * i.estimate(), 100 * i.low(), 100 * i.high()).text(2) + " %";
    }

    /** A window's miss ratio and, in brackets, its jobs missed or late and released per run. */
    private static String windowMisses(ReportModel.Cell c, String window) {
        Stats.Interval ratio = EvaluationData.windowMissRatio(c, window);
        if (Double.isNaN(ratio.estimate())) {
            return percent(ratio);
        }
        // a ratio comes from both counts, so both have a mean
        return percent(ratio) + " (" + agg(c, window + "_MISSES", 1) + " of " + num(c.metrics.get(window + "_RELEASED").mean(), 0)
                + " per run)";
    }

    /** A task's response time p99 over released jobs, infinite when a dropped or aborted job is in some run's top 1%. */
    static String response(ReportModel.Cell c, String task) {
        ReportModel.Agg a = c.metrics.get(TaskMetric.RESPONSE_P99.key(task));
        if (a == null || a.n() == 0 || a.mean() == null) {
            return "n/a";
        }
        if (a.max() != null && a.max().isInfinite()) {
            return "∞ (in at least one of " + Counts.of(a.n(), "run") + ")";
        }
        return a.interval().text(3);
    }

    /**
     * What the test says of pairs of a configuration and its variant (another profile, a load) on {@code m}: the
     * variants it separates above and below their base, each with the ratio of the means, and how many it does not,
     * e.g. "release jitter p99 higher for native [load cpu] (10.63x); not separated for 2 of 3".
     */
    private String separatedPairs(List<ReportModel.Cell[]> pairs, Metric m, String what) {
        List<String> higher = new ArrayList<>();
        List<String> lower = new ArrayList<>();
        for (ReportModel.Cell[] p : pairs) {
            Separation.Verdict v = separate(p[0], p[1], m).verdict();
            String ratio = ratio(mean(p[1], m), mean(p[0], m));
            String named = p[1].config + (ratio.isEmpty() ? "" : " (" + ratio + ")");
            if (v == Separation.Verdict.A_LOWER) {
                higher.add(named);
            } else if (v == Separation.Verdict.B_LOWER) {
                lower.add(named);
            }
        }
        List<String> said = new ArrayList<>();
        if (!higher.isEmpty()) {
            said.add("higher for " + String.join(", ", higher));
        }
        if (!lower.isEmpty()) {
            said.add("lower for " + String.join(", ", lower));
        }
        int unseparated = pairs.size() - higher.size() - lower.size();
        if (unseparated > 0) {
            said.add("not separated for " + unseparated + " of " + pairs.size());
        }
        return what + " " + String.join("; ", said);
    }

    /**
     * "At N particles, policy P, x: A ... against B ...", with whether the test separates them: the
     * two cells share their count and policy, and the sentence names both, as a table row would.
     */
    private String pairSentence(ReportModel.Cell a, ReportModel.Cell b, Metric m, String what) {
        return String.format(Locale.ROOT, "At %d particles, policy %s, %s: %s %s ms against %s %s ms. %s", a.particles, a.policy,
                what, a.config, agg(a, m, 3), b.config, agg(b, m, 3), separation(a, b, m));
    }
}
