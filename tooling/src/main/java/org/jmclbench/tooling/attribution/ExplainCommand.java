package org.jmclbench.tooling.attribution;

import java.io.PrintStream;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.Callable;
import java.util.stream.Collectors;

import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.SerializationFeature;

import org.jmclbench.tooling.cli.BadUsageException;

import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;

/** {@code jmclbench explain RUN_DIR}: why each job of one run missed its deadline or was late. */
@Command(name = "explain", mixinStandardHelpOptions = true,
        header = "Says why each missed or late job of one run missed.",
        description = {"Says why each missed or late job of one run missed: GC pauses, safepoints, JIT, "
                + "class loading, locks, waiting for another job (queued), the OS waking it late, "
                + "preemption, or plain compute.",
                "Reads the run's job lines, summary.json (its clock) and the JFR recording or GC log "
                + "in the run folder or its parents."},
        footer = {"", "Example: ./jmclbench explain results/runs/3f2a9c/"})
public final class ExplainCommand implements Callable<Integer> {

    @Parameters(paramLabel = "RUN_DIR", description = "a run folder, or a folder holding exactly one (e.g. results/runs/<run_key>)")
    Path runDir;

    @Option(names = "--events", paramLabel = "FILE",
            description = "the run's JFR recording (*.jfr) or GC log, when it is not recording.jfr or gc.log in the run folder or its parents")
    Path eventsFile;

    @Option(names = "--json", description = "print the attributions as JSON instead of a table")
    boolean json;

    @Option(names = "--limit", paramLabel = "N", defaultValue = "50",
            description = "print at most N jobs in the table (default ${DEFAULT-VALUE}; 0 = all)")
    int limit;

    @Option(names = "--os-threshold-us", paramLabel = "US", defaultValue = "1000",
            description = "a start delay below this is not a cause (default ${DEFAULT-VALUE} us)")
    long osThresholdUs;

    @Override
    public Integer call() throws Exception {
        if (limit < 0) {
            throw BadUsageException.ofOption("--limit", "'" + limit + "' is negative (0 shows all)");
        }
        if (osThresholdUs < 0) {
            throw BadUsageException.ofOption("--os-threshold-us", "'" + osThresholdUs + "' is negative");
        }
        RunEvidence run = RunEvidence.load(runDir, eventsFile);
        Attribution.Settings d = Attribution.Settings.defaults();
        Attribution.Settings settings = new Attribution.Settings(osThresholdUs * 1000, d.minOverlapNs(),
                d.preemptionRatio(), d.preemptionMinNs(), d.jobCodePrefix());
        List<JobAttribution> attributions = run.attribute(settings);
        if (json) {
            printJson(run, attributions, System.out);
        } else {
            printTable(run, attributions, System.out);
        }
        return 0;
    }

    /** " (5 dropped, 2 late)": how the jobs missed, in the report's words (skipped is dropped, terminated aborted). */
    static String byOutcome(List<JobAttribution> attributions) {
        Map<String, Long> n = attributions.stream().collect(Collectors.groupingBy(JobAttribution::outcome, Collectors.counting()));
        List<String> parts = new ArrayList<>();
        for (String[] outcome : new String[][] {{"skipped", "dropped"}, {"terminated", "aborted"}, {"late", "late"}}) {
            if (n.containsKey(outcome[0])) {
                parts.add(n.get(outcome[0]) + " " + outcome[1]);
            }
        }
        return parts.isEmpty() ? "" : " (" + String.join(", ", parts) + ")";
    }

    private void printTable(RunEvidence run, List<JobAttribution> attributions, PrintStream out) {
        out.println("run:     " + run.runDir());
        var env = run.summary().path("environment").path("runtime");
        var params = run.summary().path("parameters");
        out.println("runtime: " + env.path("vmName").asText(env.path("language").asText("?")) + " "
                + env.path("version").asText("") + ", GC " + env.path("gcNames") + "; policy "
                + params.path("policy").asText("?") + ", " + params.path("particles").asText("?") + " particles; load "
                + params.path("load").path("scenario").asText(params.path("load").asText("none")));
        out.println("events:  " + run.eventSource());
        long released = run.jobs().size();
        out.printf(Locale.ROOT, "missed or late: %d of %d jobs%s%n", attributions.size(), released, byOutcome(attributions));
        Map<String, Double> split = new LinkedHashMap<>();
        for (MetricRow m : WarmupSplit.metrics(run.jobs(), WarmupSplit.DEFAULT_BOUNDARY_NS)) {
            if (m.task().equals("all")) {
                split.put(m.metric() + "/" + m.stat(), m.value());
            }
        }
        out.printf(Locale.ROOT, "warm-up: first %.0f s: %.0f of %.0f jobs missed or late, task latency p99 %s; after: %.0f of %.0f, p99 %s%n",
                WarmupSplit.DEFAULT_BOUNDARY_NS / 1e9, split.getOrDefault("missedOrLate.warm/value", 0.0),
                split.getOrDefault("released.warm/value", 0.0), msOrDash(split.get("taskLatencyNs.warm/p99")),
                split.getOrDefault("missedOrLate.steady/value", 0.0), split.getOrDefault("released.steady/value", 0.0),
                msOrDash(split.get("taskLatencyNs.steady/p99")));
        if (attributions.isEmpty()) {
            return;
        }
        Map<String, Integer> any = Attribution.countCauses(attributions);
        Map<String, Integer> primary = Attribution.countPrimaryCauses(attributions);
        List<String> parts = new ArrayList<>();
        any.entrySet().stream().sorted((a, b) -> b.getValue() - a.getValue())
                .forEach(e -> parts.add(e.getKey() + " " + e.getValue() + " [" + primary.getOrDefault(e.getKey(), 0) + "]"));
        out.println("causes:  " + String.join(", ", parts) + "   (jobs with the cause [jobs where it is the largest])");
        out.println();
        out.printf(Locale.ROOT, "%-8s %6s %-10s %-23s %s%n", "task", "job", "outcome", "window ms", "causes, largest first");
        int shown = 0;
        for (JobAttribution a : attributions) {
            if (limit > 0 && shown++ >= limit) {
                out.println("... " + (attributions.size() - limit) + " more (--limit 0 shows all)");
                break;
            }
            List<String> causes = new ArrayList<>();
            for (Cause c : a.causes()) {
                causes.add(c.kind() + " " + String.format(Locale.ROOT, "%.1f ms", c.ns() / 1e6)
                        + (c.detail().isEmpty() ? "" : " (" + c.detail() + ")"));
            }
            out.printf(Locale.ROOT, "%-8s %6d %-10s %-23s %s%s%n", a.task(), a.index(), a.outcome(),
                    String.format(Locale.ROOT, "%.1f-%.1f", a.windowStartNs() / 1e6, a.windowEndNs() / 1e6),
                    a.blockedBy() == null ? "" : "behind " + a.blockedBy() + ": ", String.join("; ", causes));
        }
    }

    private static String msOrDash(Double ns) {
        return ns == null ? "-" : String.format(Locale.ROOT, "%.2f ms", ns / 1e6);
    }

    private static void printJson(RunEvidence run, List<JobAttribution> attributions, PrintStream out) throws Exception {
        Map<String, Object> doc = new LinkedHashMap<>();
        doc.put("runDir", run.runDir().toString());
        doc.put("events", run.eventSource());
        doc.put("causeCounts", Attribution.countCauses(attributions));
        doc.put("primaryCauseCounts", Attribution.countPrimaryCauses(attributions));
        doc.put("jobs", attributions);
        out.println(new ObjectMapper().enable(SerializationFeature.INDENT_OUTPUT).writeValueAsString(doc));
    }
}
