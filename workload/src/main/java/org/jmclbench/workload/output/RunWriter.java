package org.jmclbench.workload.output;

import java.io.BufferedWriter;
import java.io.File;
import java.io.FileOutputStream;
import java.io.IOException;
import java.io.OutputStreamWriter;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.util.Locale;

import org.jmclbench.workload.RunOptions;
import org.jmclbench.workload.data.Dataset;
import org.jmclbench.workload.engine.EngineFacts;
import org.jmclbench.core.timeline.Timeline;
import org.jmclbench.core.record.Deviation;
import org.jmclbench.core.record.JobRecords;
import org.jmclbench.workload.record.Samples;
import org.jmclbench.workload.record.Stats;

/**
 * Writes a finished run's files into its (partial) folder, per docs/FORMATS.md section 3:
 * the job files, position and deviation series, covariance, the thesis's data.txt and
 * summary.json. Runs after the measured window; allocation and I/O are fine here.
 */
public final class RunWriter {
    public static final String SCHEMA = "jmclbench-run/1";

    private final RunOptions options;
    private final Dataset dataset;
    private final Timeline timeline;
    private final JobRecords records;
    private final Environment environment;
    private EngineFacts engine = EngineFacts.NONE;
    private java.util.List<MemoryArea> memory = java.util.Collections.emptyList();

    public RunWriter(RunOptions options, Dataset dataset, Timeline timeline, JobRecords records,
            Environment environment) {
        this.options = options;
        this.dataset = dataset;
        this.timeline = timeline;
        this.records = records;
        this.environment = environment;
    }

    /** What the engine tells about how it ran, written after its kind in summary.json's {@code "engine"} object. */
    public RunWriter engine(EngineFacts facts) {
        this.engine = facts;
        return this;
    }

    /** The run's memory areas, written as summary.json's {@code "memory": {"areas": [...]}}. */
    public RunWriter memory(java.util.List<MemoryArea> areas) {
        this.memory = areas;
        return this;
    }

    /** Writes every file of the run into dir. */
    public void writeAll(File dir) throws IOException {
        Deviation dev = dataset.deviation(timeline, records);
        writeJobs(new File(dir, "odoData.txt"), Timeline.PREDICT);
        writeJobs(new File(dir, "laserData.txt"), Timeline.UPDATE);
        writePositions(new File(dir, "position.txt"), new File(dir, "positionDeviation.txt"), dev);
        if (records.cov != null) {
            writeCovariance(new File(dir, "covariance.txt"));
        }
        TaskSummary predict = TaskSummary.of(records, Timeline.PREDICT, options);
        TaskSummary update = TaskSummary.of(records, Timeline.UPDATE, options);
        TaskSummary all = TaskSummary.of(records, -1, options);
        writeData(new File(dir, "data.txt"), dev, all);
        writeText(new File(dir, "summary.json"), summary(dev, predict, update, all));
    }

    private void writeJobs(File f, int task) throws IOException {
        StringBuilder b = new StringBuilder(64 * (timeline.count(task) + 1));
        b.append("# index release_ns start_ns end_ns deadline_ns outcome cpu_ns abort_ns seen_ns\n");
        for (int k = 0; k < timeline.size(); k++) {
            if (timeline.task(k) != task) {
                continue;
            }
            b.append(timeline.taskIndex(k)).append(' ').append(records.releaseNs[k]).append(' ')
                    .append(records.startNs[k]).append(' ').append(records.endNs[k]).append(' ')
                    .append(records.deadlineNs[k]).append(' ').append(JobRecords.outcomeName(records.outcome[k]))
                    .append(' ').append(records.cpuNs[k]).append(' ').append(records.abortFromNs(k))
                    .append(' ').append(records.abortSeenFromNs(k)).append('\n');
        }
        writeText(f, b.toString());
    }

    private void writePositions(File position, File deviation, Deviation dev) throws IOException {
        StringBuilder p = new StringBuilder("# time x y theta\n");
        StringBuilder d = new StringBuilder("# time dx dy dxy dtheta\n");
        for (int i = 0; i < dev.size(); i++) {
            row(p, dev.time[i], dev.x[i], dev.y[i], dev.theta[i]);
            row(d, dev.time[i], dev.dx[i], dev.dy[i], dev.dxy[i], dev.dtheta[i]);
        }
        writeText(position, p.toString());
        writeText(deviation, d.toString());
    }

    private void writeCovariance(File f) throws IOException {
        StringBuilder b = new StringBuilder("# time cxx cxy cxt cyy cyt ctt\n");
        double[] c = records.cov;
        for (int k = 0; k < timeline.size(); k++) {
            if (timeline.task(k) == Timeline.UPDATE && records.completed(k)) {
                int o = 6 * k;
                row(b, timeline.time(k), c[o], c[o + 1], c[o + 2], c[o + 3], c[o + 4], c[o + 5]);
            }
        }
        writeText(f, b.toString());
    }

    private void writeData(File f, Deviation dev, TaskSummary all) throws IOException {
        StringBuilder b = new StringBuilder();
        b.append("deviationXY ").append(dev.meanXY()).append('\n');
        b.append("deviationX ").append(dev.meanAbsX()).append('\n');
        b.append("deviationY ").append(dev.meanAbsY()).append('\n');
        b.append("deviationAngle ").append(dev.meanAbsTheta()).append('\n');
        b.append("missCount ").append(all.missCount).append('\n');
        b.append("averageReleaseJitter ").append(all.releaseJitter.mean / 1e6).append('\n');
        b.append("averageTaskTime ").append(all.taskLatency.mean / 1e6).append('\n');
        writeText(f, b.toString());
    }

    /** The summary.json text. */
    String summary(Deviation dev, TaskSummary predict, TaskSummary update, TaskSummary all) {
        Json j = new Json();
        j.beginObject();
        j.name("schema").value(SCHEMA);
        j.name("status").value("complete");
        j.name("parameters").beginObject();
        j.name("runtimeName").value(options.effectiveRuntimeName());
        j.name("engine").value(options.engine);
        if ("rtsj".equals(options.engine)) {
            j.name("rtsjDesign").value(options.rtsjDesign.label);
        }
        j.name("particles").value(options.particles);
        j.name("number").value(options.number);
        j.name("policy").value(options.policy.label);
        j.name("ideal").value(options.ideal);
        j.name("memory").value(RunOptions.label(options.memory));
        j.name("estimate").value(RunOptions.label(options.estimate));
        j.name("resample").value(RunOptions.label(options.resample));
        j.name("init").value(RunOptions.label(options.init));
        j.name("seed").value(options.seed);
        j.name("covariance").value(options.covariance);
        j.name("timeScale").value(options.timeScale);
        j.name("warmupS").value(options.warmupS);
        j.name("spinUs").value(options.spinUs);
        j.name("cpuTime").value(options.cpuTime);
        j.name("load").beginObject();
        j.name("scenario").value(options.effectiveLoadName());
        if (options.loadAllocMbPerS > 0) {
            j.name("allocMbPerS").value(options.loadAllocMbPerS);
            j.name("allocLiveMb").value(options.loadAllocLiveMb);
        }
        j.endObject();
        j.name("dataset").beginObject();
        j.name("path").value(dataset.folder == null ? null : dataset.folder.getPath());
        j.name("name").value(dataset.name);
        j.name("scenario").value(dataset.scenario());
        j.name("odometry").value(dataset.odometryFile.getPath());
        j.name("laser").value(dataset.laserFile.getPath());
        j.name("real").value(dataset.realFile.getPath());
        j.endObject();
        j.endObject();
        j.name("environment");
        environment.writeTo(j);
        j.name("durationS").value(records.durationNs < 0 ? Double.NaN : records.durationNs / 1e9);
        j.name("missCount").value(all.missCount);
        j.name("tasks").beginObject();
        j.name("predict");
        predict.writeTo(j);
        j.name("update");
        update.writeTo(j);
        j.name("all");
        all.writeTo(j);
        j.endObject();
        writeStats(j, "dispatcherLatenessNs", dispatcherLateness());
        // Every run, ideal ones included, says which engine produced it.
        j.name("engine").beginObject();
        j.name("kind").value(options.engine);
        engine.writeTo(j);
        j.endObject();
        j.name("memory").beginObject();
        j.name("areas").beginArray();
        for (MemoryArea a : memory) {
            j.beginObject();
            j.name("name").value(a.name);
            j.name("size").value(a.size);
            nullableLong(j, "peakBytes", a.peakBytes);
            nullableLong(j, "bytesPerRelease", a.bytesPerRelease);
            if (a.releases != null) {
                nullableLong(j, "releases", a.releases);
                nullableLong(j, "allocatingReleases", a.allocatingReleases);
            }
            j.endObject();
        }
        j.endArray();
        j.endObject();
        j.name("deviation").beginObject();
        meanMax(j, "xy", dev.meanXY(), Deviation.maxAbs(dev.dxy));
        meanMax(j, "x", dev.meanAbsX(), Deviation.maxAbs(dev.dx));
        meanMax(j, "y", dev.meanAbsY(), Deviation.maxAbs(dev.dy));
        meanMax(j, "angle", dev.meanAbsTheta(), Deviation.maxAbs(dev.dtheta));
        j.endObject();
        j.endObject();
        return j.toString();
    }

    private static void nullableLong(Json j, String name, Long value) {
        j.name(name);
        if (value == null) {
            j.nullValue();
        } else {
            j.value(value.longValue());
        }
    }

    private static void meanMax(Json j, String name, double mean, double max) {
        j.name(name).beginObject().name("mean").value(mean).name("max").value(max).endObject();
    }

    private Stats dispatcherLateness() {
        Samples lateness = new Samples(records.size());
        for (int k = 0; k < records.size(); k++) {
            if (records.wakeNs[k] >= 0 && records.releaseNs[k] >= 0) {
                lateness.add(records.wakeNs[k] - records.releaseNs[k]);
            }
        }
        return lateness.stats();
    }

    /** Writes the field {@code name}, a STATS object; every field null when the sample is empty. */
    static void writeStats(Json j, String name, Stats s) {
        j.name(name).beginObject();
        j.name("count").value(s.count);
        if (s.count == 0) {
            j.name("mean").nullValue().name("stdev").nullValue().name("min").nullValue().name("p50").nullValue()
                    .name("p90").nullValue().name("p99").nullValue().name("p999").nullValue().name("max")
                    .nullValue();
        } else {
            j.name("mean").value(s.mean).name("stdev").value(s.stdev).name("min").value(s.min).name("p50")
                    .value(s.p50).name("p90").value(s.p90).name("p99").value(s.p99).name("p999").value(s.p999)
                    .name("max").value(s.max);
        }
        j.endObject();
    }

    private static void row(StringBuilder b, double... v) {
        for (int i = 0; i < v.length; i++) {
            if (i > 0) {
                b.append("  ");
            }
            b.append(String.format(Locale.ROOT, "%.16e", v[i]));
        }
        b.append('\n');
    }

    private static void writeText(File f, String text) throws IOException {
        try (Writer w = new BufferedWriter(new OutputStreamWriter(new FileOutputStream(f), StandardCharsets.UTF_8))) {
            w.write(text);
        }
    }
}
