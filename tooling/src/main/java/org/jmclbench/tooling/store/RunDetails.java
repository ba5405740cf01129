package org.jmclbench.tooling.store;

import java.util.ArrayList;
import java.util.List;

import org.jmclbench.tooling.attribution.AttributionData;

/** What the store keeps of an ok run beside its row: flattened metrics, histograms and small series. */
public final class RunDetails {

    /** One {@code metrics} row. */
    public record Metric(String task, String metric, String stat, double value) {
    }

    /** One {@code histograms} row: base64 of HdrHistogram's compressed encoding, values in ns. */
    public record Hdr(String task, String metric, String base64) {
    }

    /** One {@code series} row: {@code {"columns": [...], "rows": [[...], ...]}}. */
    public record Series(String name, String json) {
    }

    public final List<Metric> metrics = new ArrayList<>();
    public final List<Hdr> histograms = new ArrayList<>();
    public final List<Series> series = new ArrayList<>();
    public final List<MemoryAreaRow> areas = new ArrayList<>();
    /** One row per missed or late job: why it missed (org.jmclbench.tooling.attribution). */
    public final List<AttributionData.Row> attributions = new ArrayList<>();

    /** Nothing beside the row (failed, timed-out and unsupported runs). */
    public static RunDetails empty() {
        return new RunDetails();
    }
}
