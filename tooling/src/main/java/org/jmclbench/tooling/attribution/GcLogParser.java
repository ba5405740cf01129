package org.jmclbench.tooling.attribution;

import java.io.IOException;
import java.nio.file.Path;
import java.time.OffsetDateTime;
import java.time.format.DateTimeFormatter;
import java.time.format.DateTimeFormatterBuilder;
import java.time.temporal.ChronoField;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import org.jmclbench.tooling.cli.BoundedLineReader;

/**
 * Reads the GC log of a runtime without JDK Flight Recorder into {@link VmEvent}s on the run's
 * timeline: stop-the-world pauses and safepoints.
 *
 * <p>Two formats:
 * <ul>
 * <li>Unified logging (JDK 9+, {@code -Xlog:gc,gc+phases,safepoint:file=F:uptime,timenanos,level,tags}):
 *     {@code [0.634s][678598218944ns][info][gc] GC(0) Pause Young (Allocation Failure) 12M->2M(46M) 10.038ms}.
 *     A line is written when the pause ends. It is placed by its {@code timenanos} decoration
 *     (the JVM's {@code System.nanoTime}, exact), else {@code timemillis}/{@code time}/{@code utctime}
 *     (wall clock, ms), else {@code uptime}/{@code uptimenanos} plus the JVM start time (ms).
 *     Safepoints: JDK 13+ {@code Safepoint "Op", ... Total: N ns}; JDK 9-12
 *     {@code Total time for which application threads were stopped: S seconds} after
 *     {@code Entering safepoint region: Op}.</li>
 * <li>JDK 8 ({@code -verbose:gc -Xloggc:F -XX:+PrintGCDateStamps -XX:+PrintGCApplicationStoppedTime}):
 *     {@code 2026-11-22T02:12:35.123+0000: 0.161: [GC (Allocation Failure) ..., 0.0082540 secs]},
 *     written when the pause starts; placed by the date stamp, else the uptime stamp.</li>
 * </ul>
 * Lines it does not recognise are skipped: a GC log is a diagnostic, not a contract.
 */
public final class GcLogParser {
    private static final Pattern DECORATION = Pattern.compile("^\\[([^\\]]*)\\]");
    private static final Pattern UNIFIED_PAUSE = Pattern.compile(
            "GC\\((\\d+)\\)\\s+((?:[yYO]:\\s+)?Pause [^0-9]*?(?:\\([^)]*\\)\\s*)*)(?:\\s+\\S+->\\S+)?\\s+(\\d+(?:\\.\\d+)?)ms\\s*$");
    private static final Pattern USING = Pattern.compile("\\bUsing (.+?)\\s*$");
    private static final Pattern SAFEPOINT_13 = Pattern.compile("Safepoint \"([^\"]+)\".*?Total: (\\d+) ns");
    private static final Pattern SAFEPOINT_ENTER = Pattern.compile("Entering safepoint region: (.+?)\\s*$");
    private static final Pattern STOPPED = Pattern.compile(
            "Total time for which application threads were stopped: (\\d+(?:\\.\\d+)?) seconds");
    private static final Pattern JDK8_STAMPS = Pattern.compile(
            "^(?:(\\d{4}-\\d\\d-\\d\\dT\\d\\d:\\d\\d:\\d\\d\\.\\d{3}[+-]\\d{4}): )?(?:(\\d+\\.\\d+): )?(.*)$");
    private static final Pattern JDK8_PAUSE = Pattern.compile(
            "^\\[(Full GC|GC)\\s*(\\((?:[^()]|\\([^)]*\\))*\\))?.*?,\\s+(\\d+\\.\\d+) secs\\](?:\\s*\\[Times:.*)?\\s*$");
    private static final Pattern JDK8_G1_PAUSE = Pattern.compile(
            "^\\[GC (pause|remark|cleanup)\\s*(.*?),\\s+(\\d+\\.\\d+) secs\\]\\s*$");
    private static final DateTimeFormatter JDK8_DATE = new DateTimeFormatterBuilder()
            .appendPattern("yyyy-MM-dd'T'HH:mm:ss").appendFraction(ChronoField.MILLI_OF_SECOND, 3, 3, true)
            .appendPattern("xx").toFormatter();

    /** The JDK 8 {@code -Xloggc} file's third header line, written before any entry. */
    private static final String JDK8_FLAGS_HEADER = "CommandLine flags: ";

    private GcLogParser() {
    }

    /**
     * Whether {@code log} can be a GC log of either format: some line of it is one a GC log writes
     * (a unified-logging line tagged gc or safepoint, such as "Using Serial"; a JDK 8 entry or its
     * "CommandLine flags:" header), or it has no line at all (a log that --gc-log starts at run time
     * stays empty when nothing stopped the world). Another text, read by {@link #parse}, is a log of
     * no events: a wrong file that would explain nothing. Bytes that are not UTF-8 do not throw.
     */
    public static boolean isGcLog(Path log) throws IOException {
        boolean text = false;
        try (BoundedLineReader r = new BoundedLineReader(log)) {
            for (String line = r.readLine(); line != null; line = r.readLine()) {
                if (line.isBlank()) {
                    continue;
                }
                text = true;
                if (isGcLogLine(line)) {
                    return true;
                }
            }
        }
        return !text;
    }

    private static boolean isGcLogLine(String line) {
        if (line.startsWith("[")) {
            Decorated d;
            try {
                d = Decorated.of(line);
            } catch (RuntimeException e) {
                return false; // a bracketed date that is not one
            }
            return d != null && (d.tags.startsWith("gc") || d.tags.startsWith("safepoint"));
        }
        if (line.startsWith(JDK8_FLAGS_HEADER)) {
            return true;
        }
        Matcher s = JDK8_STAMPS.matcher(line);
        if (!s.matches() || (s.group(1) == null && s.group(2) == null)) {
            return false;
        }
        String rest = s.group(3);
        return rest.startsWith("[GC") || rest.startsWith("[Full GC") || STOPPED.matcher(rest).find();
    }

    /** Every pause and safepoint in the log, sorted by start. */
    public static List<VmEvent> parse(Path log, RunClock clock) throws IOException {
        EventSelection all = EventSelection.all(log);
        parse(log, clock, all);
        return all.events();
    }

    /**
     * Reads the log line by line into {@code selection}, which keeps what it needs of it.
     *
     * @throws IOException naming file:line for a line longer than {@link BoundedLineReader#MAX_LINE_CHARS}
     *                     (a runaway log), or the file when the selection holds too many events
     */
    public static void parse(Path log, RunClock clock, EventSelection selection) throws IOException {
        Lines p = new Lines(clock);
        List<VmEvent> found = new ArrayList<>();
        try (BoundedLineReader r = new BoundedLineReader(log)) {
            for (String line = r.readLine(); line != null; line = r.readLine()) {
                p.read(line, found);
                for (VmEvent e : found) {
                    selection.add(e);
                }
                found.clear();
            }
        }
    }

    /** Every pause and safepoint in these log lines, sorted by start. */
    public static List<VmEvent> parse(List<String> lines, RunClock clock) {
        List<VmEvent> out = new ArrayList<>();
        Lines p = new Lines(clock);
        for (String line : lines) {
            p.read(line, out);
        }
        out.sort(Comparator.comparingLong(VmEvent::startNs));
        return out;
    }

    /** What a line of the log means in the light of the lines before it (the collector, a safepoint entered). */
    private static final class Lines {
        private final RunClock clock;
        private String collector = "GC";
        private String pendingSafepoint;

        Lines(RunClock clock) {
            this.clock = clock;
        }

        /** Adds the events {@code line} ends to {@code out}. */
        void read(String line, List<VmEvent> out) {
            if (line.startsWith("[")) {
                Decorated d = Decorated.of(line);
                if (d == null) {
                    return;
                }
                Matcher m;
                if ((m = USING.matcher(d.message)).find() && d.tags.startsWith("gc")) {
                    collector = m.group(1);
                } else if (d.tags.startsWith("gc") && (m = UNIFIED_PAUSE.matcher(d.message)).find()) {
                    addEnded(out, VmEventKind.GC_PAUSE, d.runTime(clock), m.group(3), 1e6,
                            collector + " " + m.group(2).trim() + " #" + m.group(1));
                } else if (d.tags.startsWith("safepoint") && (m = SAFEPOINT_13.matcher(d.message)).find()) {
                    addEnded(out, VmEventKind.SAFEPOINT, d.runTime(clock), m.group(2), 1, m.group(1));
                } else if (d.tags.startsWith("safepoint") && (m = SAFEPOINT_ENTER.matcher(d.message)).find()) {
                    pendingSafepoint = m.group(1);
                } else if (d.tags.startsWith("safepoint") && (m = STOPPED.matcher(d.message)).find()) {
                    addEnded(out, VmEventKind.SAFEPOINT, d.runTime(clock), m.group(1), 1e9,
                            pendingSafepoint == null ? "safepoint" : pendingSafepoint);
                    pendingSafepoint = null;
                }
            } else {
                parseJdk8(line, clock, out);
            }
        }
    }

    private static void parseJdk8(String line, RunClock clock, List<VmEvent> out) {
        Matcher s = JDK8_STAMPS.matcher(line);
        if (!s.matches() || (s.group(1) == null && s.group(2) == null)) {
            return;
        }
        Long at;
        if (s.group(1) != null) {
            OffsetDateTime t = OffsetDateTime.parse(s.group(1), JDK8_DATE);
            at = clock.fromEpochNs(t.toEpochSecond() * 1_000_000_000L + t.getNano());
        } else if (clock.knowsJvmStart()) {
            at = clock.fromUptimeNs(Math.round(Double.parseDouble(s.group(2)) * 1e9));
        } else {
            return;
        }
        String rest = s.group(3);
        Matcher m;
        if ((m = JDK8_G1_PAUSE.matcher(rest)).matches() || (m = JDK8_PAUSE.matcher(rest)).matches()) {
            long dur = Math.round(Double.parseDouble(m.group(3)) * 1e9);
            String name = m.group(1).startsWith("GC") || m.group(1).startsWith("Full") ? m.group(1) : "GC " + m.group(1);
            String cause = m.group(2) == null || m.group(2).isBlank() ? "" : " " + m.group(2).trim();
            out.add(new VmEvent(VmEventKind.GC_PAUSE, at, at + dur, null, name + cause));
        } else if ((m = STOPPED.matcher(rest)).find()) {
            addEnded(out, VmEventKind.SAFEPOINT, at, m.group(1), 1e9, "safepoint");
        }
    }

    /**
     * A pause that ended at {@code end} (run time in ns; none when the line's time is not on the run's
     * clock) and lasted {@code duration}, a logged decimal of units of {@code nsPerUnit} nanoseconds.
     */
    private static void addEnded(List<VmEvent> out, VmEventKind kind, Long end, String duration, double nsPerUnit,
            String label) {
        if (end != null) {
            long dur = Math.round(Double.parseDouble(duration) * nsPerUnit);
            out.add(new VmEvent(kind, end - dur, end, null, label));
        }
    }

    /** A unified-logging line split into its decorations and message. */
    private record Decorated(Long timeNanos, Long epochMs, Long uptimeNs, String tags, String message) {

        static Decorated of(String line) {
            Long timeNanos = null;
            Long epochMs = null;
            Long uptimeNs = null;
            Long nanos = null;
            String tags = "";
            int pos = 0;
            Matcher m = DECORATION.matcher(line);
            while (m.region(pos, line.length()).lookingAt()) {
                String v = m.group(1).trim();
                pos = m.end();
                if (v.matches("\\d+(\\.\\d+)?s")) {
                    uptimeNs = Math.round(Double.parseDouble(v.substring(0, v.length() - 1)) * 1e9);
                } else if (v.matches("\\d+ns")) {
                    nanos = Long.parseLong(v.substring(0, v.length() - 2));
                } else if (v.matches("\\d+ms")) {
                    long ms = Long.parseLong(v.substring(0, v.length() - 2));
                    if (ms > 100_000_000_000L) {
                        epochMs = ms; // timemillis (epoch); uptimemillis stays far below
                    } else if (uptimeNs == null) {
                        uptimeNs = ms * 1_000_000L;
                    }
                } else if (v.matches("\\d{4}-\\d\\d-\\d\\dT.*")) {
                    try {
                        epochMs = OffsetDateTime.parse(v, DateTimeFormatter.ISO_OFFSET_DATE_TIME).toInstant().toEpochMilli();
                    } catch (RuntimeException e) {
                        epochMs = OffsetDateTime.parse(v, JDK8_DATE).toInstant().toEpochMilli();
                    }
                } else if (v.matches("[a-z][a-z0-9_]*(,[a-z0-9_]+)*") && !isLevel(v)) {
                    tags = v;
                }
            }
            if (pos == 0) {
                return null;
            }
            if (nanos != null) {
                // timenanos and uptimenanos look alike: uptimenanos agrees with the uptime.
                // Without an uptime beside it, an ns decoration is taken as timenanos (what JfrFlags asks for).
                boolean isUptime = uptimeNs != null && Math.abs(nanos - uptimeNs) < 50_000_000L;
                if (isUptime) {
                    uptimeNs = nanos;
                } else {
                    timeNanos = nanos;
                }
            }
            return new Decorated(timeNanos, epochMs, uptimeNs, tags, line.substring(pos).trim());
        }

        private static boolean isLevel(String v) {
            return v.equals("info") || v.equals("debug") || v.equals("trace") || v.equals("warning") || v.equals("error");
        }

        /** The line's time on the run's timeline, or null when it cannot be placed. */
        Long runTime(RunClock clock) {
            if (timeNanos != null) {
                return clock.fromNanoTime(timeNanos);
            }
            if (epochMs != null) {
                return clock.fromEpochNs(epochMs * 1_000_000L);
            }
            if (uptimeNs != null && clock.knowsJvmStart()) {
                return clock.fromUptimeNs(uptimeNs);
            }
            return null;
        }
    }
}
