package org.jmclbench.tooling.report;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;

import org.jmclbench.tooling.store.StoredRun;
import org.jmclbench.tooling.store.StoredRuns;

import org.HdrHistogram.Histogram;
import org.HdrHistogram.HistogramIterationValue;

/**
 * The series of a cell read from the store: the merged histograms' latency and abort latency
 * spectra and jitter CDF, the first repetition's task latencies, pauses and trajectory, the repetitions' deviation.
 */
final class CellSeries {

    /** Repetitions drawn in "deviation over time" per configuration. */
    static final int MAX_REPETITION_SERIES = 5;
    /** Points per series after down-sampling (the store keeps up to 2000). */
    static final int MAX_POINTS = 400;
    /** Points of a task latency series: each bucket keeps its slowest job. */
    static final int MAX_LATENCY_POINTS = 1000;

    private CellSeries() {
    }

    /** Fills the series of {@code c} from its completed runs {@code ok} (at least one). */
    static void read(StoredRuns store, List<StoredRun> ok, ReportModel.Cell c) {
    List<String> keys = ok.stream().map(r -> r.runKey).toList();
    Histogram latency = merged(store.histograms(keys, "all", "taskLatencyNs"));
    if (latency != null) {
        c.latencySpectrum = spectrum(latency);
    }
    for (String task : List.of("predict", "update")) {
        List<double[]> completion = completion(store.histograms(keys, task, "responseTimeNs"), ok, task);
        if (completion != null) {
            c.responseCompletion.put(task, completion);
        }
    }
    Histogram abort = merged(store.histograms(keys, "all", "abortLatencyNs"));
    if (abort != null) {
        c.abortSpectrum = spectrum(abort);
    }
    Histogram jitter = merged(store.histograms(keys, "all", "releaseJitterNs"));
    if (jitter != null) {
        for (HistogramIterationValue v : jitter.percentiles(5)) {
            c.jitterCdf.add(new double[] {SeriesTable.round(Math.max(1e-4, v.getValueIteratedTo() / 1e6)),
                    SeriesTable.round(v.getPercentileLevelIteratedTo() / 100.0)});
        }
    }
    StoredRun rep = ok.get(0);
    c.latencyPredict = latencyPoints(store.series(rep.runKey, "taskLatency.predict"));
    c.latencyUpdate = latencyPoints(store.series(rep.runKey, "taskLatency.update"));
    for (StoredRun r : ok.subList(0, Math.min(MAX_REPETITION_SERIES, ok.size()))) {
        SeriesTable t = SeriesTable.parse(store.series(r.runKey, "deviation"));
        if (t != null) {
            c.deviation.add(t.points(t.column("time", "t", "timeS"), 1, t.column("dxy", "deviationXY", "xy", "exy"), 1, MAX_POINTS));
            c.deviationRepetitions.add(r.repetition);
        }
    }
    pauses(c, store.series(rep.runKey, "pauses"), store.series(rep.runKey, "taskLatency.predict"),
            store.series(rep.runKey, "taskLatency.update"));
    SeriesTable t = SeriesTable.parse(store.series(rep.runKey, "trajectory"));
    if (t != null) {
        c.trajectory = t.points(t.column("x", "estX", "estimateX", "xEst"), 1, t.column("y", "estY", "estimateY", "yEst"), 1, MAX_POINTS);
        c.real = t.points(t.column("realX", "trueX", "xReal"), 1, t.column("realY", "trueY", "yReal"), 1, MAX_POINTS);
    }
    }

    /**
     * [1/(1-p), value ms, percentile p] of a histogram, up to p = 1 - 1/n for its n values: past
     * that level the n-th value is all there is, and the curve would run flat to any x.
     */
    static List<double[]> spectrum(Histogram h) {
        List<double[]> out = new ArrayList<>();
        long n = h.getTotalCount();
        for (HistogramIterationValue v : h.percentiles(5)) {
            double p = v.getPercentileLevelIteratedTo();
            double x = p >= 100 ? Double.POSITIVE_INFINITY : 100.0 / (100.0 - p);
            if (x >= n) {
                break;
            }
            out.add(new double[] {SeriesTable.round(x), SeriesTable.round(v.getValueIteratedTo() / 1e6), SeriesTable.round(p)});
        }
        double last = 100.0 * (1 - 1.0 / n); // the end of the curve: the last level n values tell
        out.add(new double[] {n, SeriesTable.round(h.getValueAtPercentile(last) / 1e6), SeriesTable.round(last)});
        return out;
    }

    /**
     * "Fraction of released jobs completed by time t" of one task: the completed jobs' response
     * times of every run that stored them (merged) over the jobs those runs released; null when no
     * run has both. A dropped or aborted job never completes, so the curve ends below 1.
     */
    static List<double[]> completion(Map<String, Histogram> histograms, List<StoredRun> ok, String task) {
        Map<String, Histogram> counted = new java.util.HashMap<>();
        double released = 0;
        for (StoredRun r : ok) {
            Double n = TaskMetric.released(r, task);
            if (histograms.containsKey(r.runKey) && n != null) {
                counted.put(r.runKey, histograms.get(r.runKey));
                released += n;
            }
        }
        Histogram h = merged(counted);
        if (h == null || released <= 0) {
            return null;
        }
        List<double[]> out = new ArrayList<>();
        out.add(new double[] {SeriesTable.round(Math.max(1e-4, h.getMinValue() / 1e6)), 0});
        // steps of 5% in value: a few hundred points from microseconds to seconds
        for (HistogramIterationValue v : h.logarithmicBucketValues(Math.max(1, h.getMinValue()), 1.05)) {
            out.add(new double[] {SeriesTable.round(Math.max(1e-4, v.getValueIteratedTo() / 1e6)),
                    SeriesTable.round(v.getTotalCountToThisValue() / released)});
        }
        return out;
    }

    /**
     * The pauses (seconds on the run's timeline) as event-index intervals, through the release
     * times of the latency series (predict's, else update's: one task, so that indices never mix),
     * so that they can be drawn on the task latency vs event index chart.
     */
    private static void pauses(ReportModel.Cell c, String pausesJson, String... latencyJson) {
        SeriesTable p = SeriesTable.parse(pausesJson);
        if (p == null || p.size() == 0) {
            return;
        }
        java.util.TreeMap<Double, Double> indexAt = new java.util.TreeMap<>();
        for (String json : latencyJson) {
            if (indexAt.size() >= 2) {
                break; // one task's jobs only: the regular predict releases, update's when predict has none
            }
            SeriesTable t = SeriesTable.parse(json);
            if (t == null) {
                continue;
            }
            int index = t.column("index", "i", "job");
            int release = t.column("releaseS", "release");
            if (index < 0 || release < 0) {
                continue;
            }
            for (int i = 0; i < t.size(); i++) {
                double s = t.value(i, release);
                double x = t.value(i, index);
                if (Double.isFinite(s) && Double.isFinite(x)) {
                    indexAt.put(s, x);
                }
            }
        }
        int start = p.column("start");
        int end = p.column("end");
        int kind = p.column("kind");
        if (indexAt.size() < 2 || start < 0 || end < 0) {
            return;
        }
        for (int i = 0; i < p.size(); i++) {
            double a = indexAt(indexAt, p.value(i, start));
            double b = indexAt(indexAt, p.value(i, end));
            if (Double.isFinite(a) && Double.isFinite(b)) {
                c.pauses.add(new double[] {SeriesTable.round(a), SeriesTable.round(b)});
                c.pauseKinds.add(kind >= 0 ? p.text(i, kind) : "pause");
            }
        }
    }

    /** The event index at time {@code s}, interpolated between the nearest releases (NaN outside them). */
    private static double indexAt(java.util.TreeMap<Double, Double> indexAt, double s) {
        Map.Entry<Double, Double> lo = indexAt.floorEntry(s);
        Map.Entry<Double, Double> hi = indexAt.ceilingEntry(s);
        if (lo == null || hi == null) {
            return Double.NaN;
        }
        if (hi.getKey().equals(lo.getKey())) {
            return lo.getValue();
        }
        return lo.getValue() + (hi.getValue() - lo.getValue()) * (s - lo.getKey()) / (hi.getKey() - lo.getKey());
    }

    private static List<double[]> latencyPoints(String json) {
        SeriesTable t = SeriesTable.parse(json);
        if (t == null) {
            return new ArrayList<>();
        }
        int index = t.column("index", "i", "job");
        int ns = t.column("latencyNs", "taskLatencyNs", "latency", "taskLatency");
        if (ns >= 0) {
            return t.peakPoints(index, 1, ns, 1e-6, MAX_LATENCY_POINTS);
        }
        int ms = t.column("latencyMs", "taskLatencyMs");
        if (ms >= 0) {
            return t.peakPoints(index, 1, ms, 1, MAX_LATENCY_POINTS);
        }
        int start = t.column("startNs", "start");
        int end = t.column("endNs", "end");
        List<double[]> out = new ArrayList<>();
        if (index < 0 || start < 0 || end < 0) {
            return out;
        }
        double step = Math.max(1.0, (double) t.size() / MAX_LATENCY_POINTS);
        for (double d = 0; d < t.size(); d += step) {
            int i = (int) d;
            double s = t.value(i, start);
            double e = t.value(i, end);
            if (Double.isFinite(s) && Double.isFinite(e) && s >= 0 && e >= 0) {
                out.add(new double[] {t.value(i, index), SeriesTable.round((e - s) / 1e6)});
            }
        }
        return out;
    }

    private static Histogram merged(Map<String, Histogram> histograms) {
        Histogram sum = null;
        for (Histogram h : histograms.values()) {
            if (sum == null) {
                sum = new Histogram(h.getNumberOfSignificantValueDigits());
                sum.setAutoResize(true);
            }
            sum.add(h);
        }
        return sum == null || sum.getTotalCount() == 0 ? null : sum;
    }
}
