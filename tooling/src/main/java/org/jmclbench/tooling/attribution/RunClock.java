package org.jmclbench.tooling.attribution;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;

/**
 * Where the run's time base (ns from the run start, on {@code System.nanoTime}) sits on the
 * other clocks the runtime's own records use, so that JFR events and GC log lines can be
 * placed on the jobs' timeline. Written by the workload as {@code summary.json}'s
 * {@code engine.clock} object (docs/FORMATS.md section 4).
 *
 * @param runStartEpochNs  wall-clock time of the run start, ns since the epoch (JFR timestamps)
 * @param runStartNanoTime {@code System.nanoTime()} at the run start (GC log {@code timenanos})
 * @param jvmStartEpochMs  the JVM's start time, ms since the epoch (GC log uptime), or -1
 */
public record RunClock(long runStartEpochNs, long runStartNanoTime, long jvmStartEpochMs) {

    /** Reads the clock of a summary.json ({@code engine.clock}, or a top-level {@code clock}); null when the run has none. */
    public static RunClock fromSummary(JsonNode summary) {
        JsonNode c = summary == null ? null : summary.path("engine").get("clock");
        if (c == null && summary != null) {
            c = summary.get("clock");
        }
        if (c == null || !c.hasNonNull("runStartEpochNs") || !c.hasNonNull("runStartNanoTime")) {
            return null;
        }
        return new RunClock(c.get("runStartEpochNs").asLong(), c.get("runStartNanoTime").asLong(),
                c.hasNonNull("jvmStartEpochMs") ? c.get("jvmStartEpochMs").asLong() : -1);
    }

    /** Reads summary.json's clock; null when the file has none. */
    public static RunClock fromSummaryFile(Path summaryJson) throws IOException {
        return fromSummary(new ObjectMapper().readTree(summaryJson.toFile()));
    }

    /** Reads the fixtures' {@code clock.txt}: {@code runStartEpochNs runStartNanoTime [jvmStartEpochMs]}. */
    public static RunClock fromText(Path file) throws IOException {
        String[] f = Files.readString(file).trim().split("\\s+");
        return new RunClock(Long.parseLong(f[0]), Long.parseLong(f[1]), f.length > 2 ? Long.parseLong(f[2]) : -1);
    }

    /** Run time (ns from the run start) of a wall-clock instant given in ns since the epoch. */
    public long fromEpochNs(long epochNs) {
        return epochNs - runStartEpochNs;
    }

    /** Run time of a {@code System.nanoTime()} value. */
    public long fromNanoTime(long nanoTime) {
        return nanoTime - runStartNanoTime;
    }

    /** Run time of a JVM uptime in ns; needs {@link #jvmStartEpochMs} (millisecond precision). */
    public long fromUptimeNs(long uptimeNs) {
        if (jvmStartEpochMs < 0) {
            throw new IllegalStateException("the run did not record the JVM start time; uptime stamps cannot be placed");
        }
        return jvmStartEpochMs * 1_000_000L + uptimeNs - runStartEpochNs;
    }

    /** True when uptime stamps can be placed on the run's timeline. */
    public boolean knowsJvmStart() {
        return jvmStartEpochMs >= 0;
    }
}
