package org.jmclbench.tooling.attribution;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.databind.ObjectMapper;

import org.jmclbench.tooling.cli.BadUsageException;

/**
 * What the store keeps of a run's attribution (docs/FORMATS.md section 5): one
 * {@code attributions} row per missed or late job, the per-run cause counts and the warm-up
 * split as {@code metrics} rows, and the run's pauses as the {@code pauses} series (for the
 * report's pause bands on the latency timeline).
 *
 * @param rows    one per missed or late job
 * @param metrics {@code run/cause.<kind>/count|primary}, {@code run/cause.jobs/count},
 *                {@code run/cause.events/count}, and the {@link WarmupSplit} rows
 * @param pauses  the {@code pauses} series JSON: {@code {"columns": ["start", "end", "kind", "detail"], "rows": [...]}},
 *                times in seconds from the run start like the latency series; the longest
 *                {@link #MAX_PAUSES} when there are more
 */
public record AttributionData(List<Row> rows, List<MetricRow> metrics, String pauses) {
    /** The most pauses the series keeps (the longest). */
    public static final int MAX_PAUSES = 2000;
    private static final ObjectMapper JSON = new ObjectMapper();

    /** One {@code attributions} row. */
    public record Row(String task, int jobIndex, String outcome, String causesJson) {
    }

    /**
     * Attributes the run in {@code dir} (a run folder or a folder holding one) for the store.
     *
     * @throws IOException       when its event capture is there but unreadable: attributed from its job
     *                           lines alone, it would be stored as a run with no capture, its pauses told as
     *                           {@code os} or {@code preemption}
     * @throws BadUsageException when a file of it cannot be used (a runaway line, too many events)
     */
    public static AttributionData of(Path dir) throws IOException, BadUsageException {
        RunEvidence run = RunEvidence.load(dir);
        if (run.eventProblem() != null) {
            throw new IOException(run.eventProblem());
        }
        return of(run, Attribution.Settings.defaults(), WarmupSplit.DEFAULT_BOUNDARY_NS);
    }

    /** Attributes a loaded run. */
    public static AttributionData of(RunEvidence run, Attribution.Settings settings, long warmupBoundaryNs) {
        List<JobAttribution> attributions = run.attribute(settings);
        List<Row> rows = new ArrayList<>();
        for (JobAttribution a : attributions) {
            rows.add(new Row(a.task(), a.index(), a.outcome(), causesJson(a)));
        }
        List<MetricRow> metrics = new ArrayList<>();
        metrics.add(new MetricRow("run", "cause.jobs", "count", attributions.size()));
        metrics.add(new MetricRow("run", "cause.events", "count", run.eventsRead()));
        Map<String, Integer> primary = Attribution.countPrimaryCauses(attributions);
        for (Map.Entry<String, Integer> e : Attribution.countCauses(attributions).entrySet()) {
            metrics.add(new MetricRow("run", "cause." + e.getKey(), "count", e.getValue()));
            metrics.add(new MetricRow("run", "cause." + e.getKey(), "primary", primary.getOrDefault(e.getKey(), 0)));
        }
        metrics.addAll(WarmupSplit.metrics(run.jobs(), warmupBoundaryNs));
        return new AttributionData(rows, metrics, pausesJson(run));
    }

    private static String causesJson(JobAttribution a) {
        Map<String, Object> doc = new LinkedHashMap<>();
        doc.put("windowStartNs", a.windowStartNs());
        doc.put("windowEndNs", a.windowEndNs());
        doc.put("blockedBy", a.blockedBy());
        doc.put("causes", a.causes());
        return write(doc);
    }

    private static String pausesJson(RunEvidence run) {
        long end = EventSelection.runEndNs(run.jobs());
        List<VmEvent> pauses = run.events().stream()
                .filter(e -> e.kind() == VmEventKind.GC_PAUSE || e.kind() == VmEventKind.SAFEPOINT)
                .filter(e -> EventSelection.inRun(e.startNs(), e.endNs(), end)).toList();
        if (pauses.size() > MAX_PAUSES) {
            pauses = pauses.stream().sorted(Comparator.comparingLong(VmEvent::durationNs).reversed()).limit(MAX_PAUSES)
                    .sorted(Comparator.comparingLong(VmEvent::startNs)).toList();
        }
        List<Object[]> rows = new ArrayList<>();
        for (VmEvent e : pauses) {
            rows.add(new Object[] {e.startNs() / 1e9, e.endNs() / 1e9, e.kind().cause(), e.detail()});
        }
        Map<String, Object> doc = new LinkedHashMap<>();
        doc.put("columns", List.of("start", "end", "kind", "detail"));
        doc.put("rows", rows);
        return write(doc);
    }

    private static String write(Object o) {
        try {
            return JSON.writeValueAsString(o);
        } catch (JsonProcessingException e) {
            throw new IllegalStateException(e);
        }
    }
}
