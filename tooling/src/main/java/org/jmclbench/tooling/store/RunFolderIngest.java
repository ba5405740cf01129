package org.jmclbench.tooling.store;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Base64;
import java.util.Iterator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.function.Function;

import org.HdrHistogram.Histogram;
import org.jmclbench.tooling.attribution.JobFileReader;
import org.jmclbench.tooling.cli.BoundedLineReader;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;

/**
 * Turns a complete run folder (docs/FORMATS.md section 3) into what the store keeps of it: the
 * flattened summary, an HdrHistogram per task and timing metric built from every job line, and
 * down-sampled series, so that the report needs nothing but the database.
 */
public final class RunFolderIngest {

    /** The most rows a series keeps. */
    public static final int MAX_SERIES_ROWS = 2000;

    private static final ObjectMapper JSON = new ObjectMapper();
    private static final String[] COUNTS = {"released", "completed", "done", "late", "skipped", "terminated", "missCount",
        "deadlineMisses", "missRatio", "abortsCompleted"};
    /** Their numeric stats; responseTimeReleasedNs' "inf" quantiles stay in the summary, where the report reads them. */
    private static final String[] TIMINGS = {"releaseJitterNs", "taskLatencyNs", "responseTimeNs", "cpuNs", "responseTimeReleasedNs", "abortLatencyNs",
        "abortNoticeNs", "abortStopNs"};
    private static final String[] STATS = {"count", "mean", "stdev", "min", "p50", "p90", "p99", "p999", "max"};

    private RunFolderIngest() {
    }

    /** One job line of odoData.txt / laserData.txt; {@code abort} is -1 in run folders from before its column. */
    record Job(long index, long release, long start, long end, long deadline, String outcome, long cpu, long abort) {
        boolean completed() {
            return outcome.equals("done") || outcome.equals("late");
        }
    }

    /**
     * Reads the run folder {@code dir} (whose summary.json was validated) into metrics, histograms and
     * series; {@code realFile} is the dataset's ground truth for the trajectory (null: none).
     *
     * @throws IOException when a file the format promises is missing or malformed
     */
    public static RunDetails ingest(Path dir, JsonNode summary, Path realFile) throws IOException {
        RunDetails d = new RunDetails();
        flattenSummary(summary, d);
        d.areas.addAll(memoryAreas(summary));
        Map<String, List<Job>> jobs = new LinkedHashMap<>();
        jobs.put("predict", releasedJobs(dir.resolve("odoData.txt"), summary, "predict"));
        jobs.put("update", releasedJobs(dir.resolve("laserData.txt"), summary, "update"));
        List<Job> all = new ArrayList<>();
        jobs.values().forEach(all::addAll);
        jobs.put("all", all);
        for (Map.Entry<String, List<Job>> e : jobs.entrySet()) {
            Histogram jitter = new Histogram(3);
            Histogram latency = new Histogram(3);
            Histogram response = new Histogram(3);
            Histogram abort = new Histogram(3);
            for (Job j : e.getValue()) {
                if (j.abort() >= 0 && j.end() >= j.abort()) {
                    abort.recordValue(j.end() - j.abort());
                }
                if (j.start() >= 0) {
                    jitter.recordValue(Math.max(0, j.start() - j.release()));
                }
                if (j.completed() && j.start() >= 0 && j.end() >= 0) {
                    latency.recordValue(Math.max(0, j.end() - j.start()));
                    response.recordValue(Math.max(0, j.end() - j.release()));
                }
            }
            d.histograms.add(new RunDetails.Hdr(e.getKey(), "releaseJitterNs", encode(jitter)));
            d.histograms.add(new RunDetails.Hdr(e.getKey(), "taskLatencyNs", encode(latency)));
            d.histograms.add(new RunDetails.Hdr(e.getKey(), "responseTimeNs", encode(response)));
            if (abort.getTotalCount() > 0) {
                d.histograms.add(new RunDetails.Hdr(e.getKey(), "abortLatencyNs", encode(abort)));
            }
        }
        for (String task : List.of("predict", "update")) {
            d.series.add(new RunDetails.Series("taskLatency." + task, latencySeries(jobs.get(task))));
        }
        Path deviation = dir.resolve("positionDeviation.txt");
        if (Files.isRegularFile(deviation)) {
            List<double[]> rows = readOdometryRows(deviation, 5, summary);
            d.series.add(new RunDetails.Series("deviation",
                    seriesJson(List.of("time", "dx", "dy", "dxy", "dtheta"), strided(rows))));
        }
        Path position = dir.resolve("position.txt");
        if (Files.isRegularFile(position)) {
            d.series.add(new RunDetails.Series("trajectory", trajectory(readOdometryRows(position, 4, summary),
                    realFile != null && Files.isRegularFile(realFile) ? readNumbers(realFile, 4) : List.of())));
        }
        return d;
    }

    /** Every number of summary.json that a query may want, as (task, metric, stat, value) rows. */
    static void flattenSummary(JsonNode s, RunDetails d) {
        JsonNode tasks = s.path("tasks");
        for (String task : List.of("predict", "update", "all")) {
            JsonNode t = tasks.path(task);
            for (String c : COUNTS) {
                addNumber(d, task, c, "value", t.get(c));
            }
            for (String m : TIMINGS) {
                addStats(d, task, m, t.get(m));
            }
        }
        addStats(d, "dispatcher", "latenessNs", s.get("dispatcherLatenessNs"));
        addNumber(d, "run", "missCount", "value", s.get("missCount"));
        addNumber(d, "run", "durationS", "value", s.get("durationS"));
        JsonNode dev = s.path("deviation");
        for (Map.Entry<String, String> e : Map.of("xy", "deviationXY", "x", "deviationX", "y", "deviationY",
                "angle", "deviationAngle").entrySet()) {
            JsonNode n = dev.get(e.getKey());
            if (n != null && n.isObject()) {
                for (Iterator<Map.Entry<String, JsonNode>> it = n.fields(); it.hasNext(); ) {
                    Map.Entry<String, JsonNode> f = it.next();
                    addNumber(d, "run", e.getValue(), f.getKey(), f.getValue());
                }
            }
        }
    }

    /**
     * The memory areas of summary.json ({@code memory.areas}; none when absent).
     *
     * @throws IOException when they are not an array of areas with distinct names and numbers or nulls
     */
    static List<MemoryAreaRow> memoryAreas(JsonNode summary) throws IOException {
        JsonNode areas = summary.path("memory").path("areas");
        List<MemoryAreaRow> out = new ArrayList<>();
        if (areas.isMissingNode() || areas.isNull()) {
            return out;
        }
        if (!areas.isArray()) {
            throw new IOException("summary.json: memory.areas is not an array");
        }
        java.util.Set<String> names = new java.util.HashSet<>();
        for (JsonNode a : areas) {
            String name = a.path("name").isTextual() ? a.path("name").asText() : "";
            if (name.isEmpty() || !names.add(name)) {
                throw new IOException("summary.json: memory.areas: " + (name.isEmpty() ? "an area without a name" : "area '" + name + "' twice"));
            }
            Double size = bytes(a, "size", name);
            Double peak = bytes(a, "peakBytes", name);
            out.add(new MemoryAreaRow(name, size == null ? null : Math.round(size), peak == null ? null : Math.round(peak),
                    bytes(a, "bytesPerRelease", name)));
        }
        return out;
    }

    private static Double bytes(JsonNode area, String field, String name) throws IOException {
        JsonNode v = area.path(field);
        if (v.isMissingNode() || v.isNull()) {
            return null;
        }
        if (!v.isNumber() || !Double.isFinite(v.asDouble()) || v.asDouble() < 0) {
            throw new IOException("summary.json: memory area '" + name + "': " + field + " is not a byte count: " + v);
        }
        return v.asDouble();
    }

    private static void addStats(RunDetails d, String task, String metric, JsonNode stats) {
        if (stats == null || !stats.isObject()) {
            return;
        }
        for (String st : STATS) {
            addNumber(d, task, metric, st, stats.get(st));
        }
    }

    private static void addNumber(RunDetails d, String task, String metric, String stat, JsonNode v) {
        if (v != null && v.isNumber() && Double.isFinite(v.asDouble())) {
            d.metrics.add(new RunDetails.Metric(task, metric, stat, v.asDouble()));
        }
    }

    /**
     * The job lines of {@code task}, which must be as many as summary.json says were released (one
     * line a released job, docs/FORMATS.md section 3): a summary that claims jobs its job file does
     * not hold (a runtime cut short, a file cut at a line end) would store counts no job backs.
     */
    static List<Job> releasedJobs(Path file, JsonNode summary, String task) throws IOException {
        long released = released(summary, task);
        // read no further than one line past the count: a runaway file of short lines is refused there
        List<Job> jobs = readRows(file, 7, released + 1, RunFolderIngest::job);
        if (jobs.size() > released) {
            throw new IOException(file + ": more than " + released + " job lines, but summary.json says " + released + " "
                    + task + " jobs were released");
        }
        String mismatch = JobFileReader.releasedMismatch(file, jobs.size(), summary, task);
        if (mismatch != null) {
            throw new IOException(mismatch);
        }
        return jobs;
    }

    /** The jobs summary.json says {@code task} released, or Long.MAX_VALUE - 1 where it says none (no bound). */
    private static long released(JsonNode summary, String task) {
        JsonNode n = summary.path("tasks").path(task).path("released");
        return n.canConvertToLong() && n.asLong() >= 0 ? Math.min(n.asLong(), Long.MAX_VALUE - 1) : Long.MAX_VALUE - 1;
    }

    private static Job job(String[] f) {
        return new Job(Long.parseLong(f[0]), Long.parseLong(f[1]), Long.parseLong(f[2]),
                Long.parseLong(f[3]), Long.parseLong(f[4]), f[5], Long.parseLong(f[6]),
                f.length > 7 ? Long.parseLong(f[7]) : -1);
    }

    /**
     * The rows of a file of one row per odometry time (position.txt, positionDeviation.txt): at most
     * as many as summary.json says predict jobs were released.
     */
    static List<double[]> readOdometryRows(Path file, int columns, JsonNode summary) throws IOException {
        long released = released(summary, "predict");
        List<double[]> rows = readNumbers(file, columns, released + 1);
        if (rows.size() > released) {
            throw new IOException(file + ": more than " + released + " rows, one an odometry time, but summary.json says "
                    + released + " predict jobs were released");
        }
        return rows;
    }

    static List<double[]> readNumbers(Path file, int columns) throws IOException {
        return readNumbers(file, columns, Long.MAX_VALUE);
    }

    private static List<double[]> readNumbers(Path file, int columns, long maxRows) throws IOException {
        return readRows(file, columns, maxRows, f -> {
            double[] r = new double[columns];
            for (int i = 0; i < columns; i++) {
                r[i] = Double.parseDouble(f[i]);
            }
            return r;
        });
    }

    /**
     * The rows of a whitespace-separated data file (blank and {@code #} lines skipped), each of at
     * least {@code columns} fields, parsed by {@code row}, read line by line and no further than
     * {@code maxRows} rows; a short row or a bad number is an IOException naming file:line.
     */
    private static <T> List<T> readRows(Path file, int columns, long maxRows, Function<String[], T> row) throws IOException {
        List<T> rows = new ArrayList<>();
        try (BoundedLineReader r = new BoundedLineReader(file)) {
            for (String line = r.readLine(); line != null && rows.size() < maxRows; line = r.readLine()) {
                String l = line.strip();
                if (l.isEmpty() || l.startsWith("#")) {
                    continue;
                }
                String[] f = l.split("\\s+");
                if (f.length < columns) {
                    throw new IOException(file + ":" + r.lineNumber() + ": expected " + columns + " columns, found " + f.length);
                }
                try {
                    rows.add(row.apply(f));
                } catch (NumberFormatException e) {
                    throw new IOException(file + ":" + r.lineNumber() + ": not a number: " + e.getMessage());
                }
            }
        }
        return rows;
    }

    /** The longest line of a data file read (a job line is under 200 characters). */
    public static final int MAX_LINE_CHARS = BoundedLineReader.MAX_LINE_CHARS;

    static String encode(Histogram h) {
        ByteBuffer buf = ByteBuffer.allocate(h.getNeededByteBufferCapacity());
        int n = h.encodeIntoCompressedByteBuffer(buf);
        byte[] bytes = new byte[n];
        buf.flip();
        buf.get(bytes);
        return Base64.getEncoder().encodeToString(bytes);
    }

    /** Decodes a {@code histograms.hdr} value (for readers and tests). */
    public static Histogram decode(String base64) {
        try {
            return Histogram.decodeFromCompressedByteBuffer(ByteBuffer.wrap(Base64.getDecoder().decode(base64)), 0);
        } catch (java.util.zip.DataFormatException e) {
            throw new IllegalArgumentException("not an HdrHistogram: " + e.getMessage(), e);
        }
    }

    /**
     * Task latency per job: columns index, releaseS, taskLatencyNs, responseTimeNs, outcome; above
     * {@link #MAX_SERIES_ROWS} jobs, each bucket keeps its slowest job so that peaks survive.
     */
    static String latencySeries(List<Job> jobs) {
        List<Object[]> rows = new ArrayList<>();
        for (Job j : jobs) {
            boolean timed = j.completed() && j.start() >= 0 && j.end() >= 0;
            rows.add(new Object[] {j.index(), j.release() / 1e9, timed ? (Object) (j.end() - j.start()) : null,
                    timed ? (Object) (j.end() - j.release()) : null, j.outcome()});
        }
        List<Object[]> kept = rows;
        if (rows.size() > MAX_SERIES_ROWS) {
            kept = new ArrayList<>();
            int bucket = (rows.size() + MAX_SERIES_ROWS - 1) / MAX_SERIES_ROWS;
            for (int i = 0; i < rows.size(); i += bucket) {
                Object[] best = rows.get(i);
                for (int k = i + 1; k < Math.min(rows.size(), i + bucket); k++) {
                    Object[] r = rows.get(k);
                    if (r[2] != null && (best[2] == null || (Long) r[2] > (Long) best[2])) {
                        best = r;
                    }
                }
                kept.add(best);
            }
        }
        ObjectNode root = JSON.createObjectNode();
        ArrayNode cols = root.putArray("columns");
        List.of("index", "releaseS", "taskLatencyNs", "responseTimeNs", "outcome").forEach(cols::add);
        ArrayNode out = root.putArray("rows");
        for (Object[] r : kept) {
            ArrayNode a = out.addArray();
            a.add((Long) r[0]);
            a.add((Double) r[1]);
            if (r[2] == null) a.addNull(); else a.add((Long) r[2]);
            if (r[3] == null) a.addNull(); else a.add((Long) r[3]);
            a.add((String) r[4]);
        }
        return root.toString();
    }

    /** Estimated trajectory with the real one at the nearest ground-truth time. */
    static String trajectory(List<double[]> estimate, List<double[]> real) {
        List<double[]> rows = new ArrayList<>();
        int k = 0;
        for (double[] e : estimate) {
            double[] r = new double[7];
            System.arraycopy(e, 0, r, 0, 4);
            if (real.isEmpty()) {
                r[4] = r[5] = r[6] = Double.NaN;
            } else {
                while (k + 1 < real.size() && Math.abs(real.get(k + 1)[0] - e[0]) <= Math.abs(real.get(k)[0] - e[0])) {
                    k++;
                }
                r[4] = real.get(k)[1];
                r[5] = real.get(k)[2];
                r[6] = real.get(k)[3];
            }
            rows.add(r);
        }
        return seriesJson(List.of("time", "x", "y", "theta", "realX", "realY", "realTheta"), strided(rows));
    }

    /** Every k-th row (and the last) so that at most {@link #MAX_SERIES_ROWS} remain. */
    static List<double[]> strided(List<double[]> rows) {
        if (rows.size() <= MAX_SERIES_ROWS) {
            return rows;
        }
        int stride = (rows.size() + MAX_SERIES_ROWS - 2) / (MAX_SERIES_ROWS - 1);
        List<double[]> out = new ArrayList<>();
        for (int i = 0; i < rows.size(); i += stride) {
            out.add(rows.get(i));
        }
        if (out.get(out.size() - 1) != rows.get(rows.size() - 1)) {
            out.add(rows.get(rows.size() - 1));
        }
        return out;
    }

    static String seriesJson(List<String> columns, List<double[]> rows) {
        ObjectNode root = JSON.createObjectNode();
        ArrayNode cols = root.putArray("columns");
        columns.forEach(cols::add);
        ArrayNode out = root.putArray("rows");
        for (double[] r : rows) {
            ArrayNode a = out.addArray();
            for (double v : r) {
                if (Double.isFinite(v)) a.add(v); else a.addNull();
            }
        }
        return root.toString();
    }
}
