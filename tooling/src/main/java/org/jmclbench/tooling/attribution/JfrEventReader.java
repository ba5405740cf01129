package org.jmclbench.tooling.attribution;

import java.io.IOException;
import java.nio.file.Path;
import java.time.Instant;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;

import jdk.jfr.consumer.RecordedEvent;
import jdk.jfr.consumer.RecordedMethod;
import jdk.jfr.consumer.RecordedThread;
import jdk.jfr.consumer.RecordingFile;

/**
 * Reads a JFR recording made with our {@code jmclbench.jfc} (after the run, with the JDK's own
 * {@code jdk.jfr.consumer}) into {@link VmEvent}s on the run's timeline.
 *
 * <p>JFR timestamps are wall-clock instants (the chunk's start time plus a monotonic tick
 * count); they are placed with {@link RunClock#fromEpochNs}. Pauses come from
 * {@code jdk.GCPhasePause} joined by {@code gcId} with {@code jdk.GarbageCollection} for the
 * collector and cause; safepoints from {@code jdk.SafepointBegin}/{@code jdk.SafepointEnd}
 * paired by {@code safepointId}, named after the {@code jdk.ExecuteVMOperation} inside them.
 */
public final class JfrEventReader {
    private JfrEventReader() {
    }

    /** Every event of interest in the recording, sorted by start. */
    public static List<VmEvent> read(Path recording, RunClock clock) throws IOException {
        List<RecordedEvent> pauses = new ArrayList<>();
        Map<Long, String> collections = new HashMap<>();
        Map<Long, RecordedEvent> gcWhole = new HashMap<>();
        Map<Long, RecordedEvent> safepointBegin = new HashMap<>();
        Map<Long, RecordedEvent> safepointEnd = new HashMap<>();
        List<RecordedEvent> vmOperations = new ArrayList<>();
        List<VmEvent> out = new ArrayList<>();

        for (RecordedEvent e : RecordingFile.readAllEvents(recording)) {
            String type = e.getEventType().getName();
            switch (type) {
                case "jdk.GarbageCollection" -> {
                    long id = e.getLong("gcId");
                    collections.put(id, e.getString("name") + " (" + e.getString("cause") + ")");
                    gcWhole.put(id, e);
                }
                case "jdk.GCPhasePause" -> pauses.add(e);
                case "jdk.SafepointBegin" -> safepointBegin.put(e.getLong("safepointId"), e);
                case "jdk.SafepointEnd" -> safepointEnd.put(e.getLong("safepointId"), e);
                case "jdk.ExecuteVMOperation" -> vmOperations.add(e);
                case "jdk.Compilation" -> out.add(new VmEvent(VmEventKind.COMPILATION,
                        at(clock, e.getStartTime()), at(clock, e.getEndTime()), threadName(e),
                        methodName(e.getValue("method")) + " level " + e.getValue("compileLevel")
                                + (e.getBoolean("isOsr") ? " osr" : "")));
                case "jdk.Deoptimization" -> out.add(new VmEvent(VmEventKind.DEOPTIMIZATION,
                        at(clock, e.getStartTime()), at(clock, e.getEndTime()), threadName(e),
                        methodName(e.getValue("method")) + " " + e.getValue("reason")));
                case "jdk.ClassLoad" -> out.add(new VmEvent(VmEventKind.CLASS_LOAD,
                        at(clock, e.getStartTime()), at(clock, e.getEndTime()), threadName(e),
                        className(e)));
                case "jdk.ThreadPark", "jdk.JavaMonitorEnter" -> out.add(new VmEvent(VmEventKind.THREAD_BLOCKED,
                        at(clock, e.getStartTime()), at(clock, e.getEndTime()), threadName(e),
                        type.equals("jdk.ThreadPark") ? "park" : "monitor enter"));
                default -> { }
            }
        }

        Set<Long> pausedIds = new HashSet<>();
        for (RecordedEvent p : pauses) {
            long id = p.getLong("gcId");
            pausedIds.add(id);
            String gc = collections.getOrDefault(id, "GC");
            out.add(new VmEvent(VmEventKind.GC_PAUSE, at(clock, p.getStartTime()), at(clock, p.getEndTime()), null,
                    gc + " " + p.getString("name") + " #" + id));
        }
        // A collection recorded without its pause phases (phase events disabled, or an old JDK)
        // that paused for all of its duration is one pause.
        for (Map.Entry<Long, RecordedEvent> g : gcWhole.entrySet()) {
            RecordedEvent e = g.getValue();
            if (!pausedIds.contains(g.getKey()) && e.getDuration("sumOfPauses").equals(e.getDuration())) {
                out.add(new VmEvent(VmEventKind.GC_PAUSE, at(clock, e.getStartTime()), at(clock, e.getEndTime()), null,
                        collections.get(g.getKey()) + " #" + g.getKey()));
            }
        }
        for (Map.Entry<Long, RecordedEvent> b : safepointBegin.entrySet()) {
            RecordedEvent end = safepointEnd.get(b.getKey());
            if (end == null) {
                continue; // the recording stopped inside this safepoint
            }
            long from = at(clock, b.getValue().getStartTime());
            long to = at(clock, end.getEndTime());
            String op = "safepoint #" + b.getKey();
            for (RecordedEvent v : vmOperations) {
                long vs = at(clock, v.getStartTime());
                if (vs >= from && vs <= to) {
                    op = v.getString("operation") + " #" + b.getKey();
                    break;
                }
            }
            out.add(new VmEvent(VmEventKind.SAFEPOINT, from, Math.max(from, to), null, op));
        }
        out.sort(Comparator.comparingLong(VmEvent::startNs));
        return out;
    }

    private static long at(RunClock clock, Instant t) {
        return clock.fromEpochNs(epochNs(t));
    }

    private static long epochNs(Instant t) {
        return t.getEpochSecond() * 1_000_000_000L + t.getNano();
    }

    private static String threadName(RecordedEvent e) {
        RecordedThread t = e.getThread();
        if (t == null) {
            return null;
        }
        return t.getJavaName() != null ? t.getJavaName() : t.getOSName();
    }

    private static String methodName(Object value) {
        if (value instanceof RecordedMethod m) {
            return m.getType().getName() + "." + m.getName();
        }
        return "?";
    }

    private static String className(RecordedEvent e) {
        Object c = e.getValue("loadedClass");
        return c instanceof jdk.jfr.consumer.RecordedClass rc ? rc.getName() : "?";
    }
}
