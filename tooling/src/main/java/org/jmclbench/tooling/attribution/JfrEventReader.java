package org.jmclbench.tooling.attribution;

import java.io.IOException;
import java.nio.file.Path;
import java.time.Instant;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;

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
        EventSelection all = EventSelection.all(recording);
        read(recording, clock, all);
        return all.events();
    }

    /** A pause phase, waiting for its collection's name (the collection's event comes after its phases). */
    private record Phase(long gcId, long from, long to, String name) {
    }

    /** A collection: its name and cause, and its span when it paused for all of it (else null). */
    private record Collection(String name, long[] wholePause) {
    }

    /**
     * Reads the recording event by event into {@code selection} (never every event at once: a
     * recording may be far larger than the harness's memory). Pauses and safepoints are put
     * together from several events; their parts are held while they are in the run.
     */
    public static void read(Path recording, RunClock clock, EventSelection selection) throws IOException {
        List<Phase> phases = new ArrayList<>();
        Map<Long, Collection> collections = new HashMap<>();
        Map<Long, Long> openBegin = new HashMap<>(); // a safepoint's side waiting for the other, by id
        Map<Long, Long> openEnd = new HashMap<>();
        List<long[]> safepoints = new ArrayList<>(); // {id, from, to} of those wanted, named when all is read
        TreeMap<Long, String> vmOperations = new TreeMap<>();
        Map<String, String> names = new HashMap<>(); // one copy of each repeated name

        try (RecordingFile file = new RecordingFile(recording)) {
            while (file.hasMoreEvents()) {
                RecordedEvent e = file.readEvent();
                String type = e.getEventType().getName();
                switch (type) {
                    case "jdk.GarbageCollection" -> {
                        long from = at(clock, e.getStartTime());
                        long to = at(clock, e.getEndTime());
                        if (selection.wanted(from, to)) {
                            boolean whole = e.getDuration("sumOfPauses").equals(e.getDuration());
                            collections.put(e.getLong("gcId"), new Collection(
                                    names.computeIfAbsent(e.getString("name") + " (" + e.getString("cause") + ")", k -> k),
                                    whole ? new long[] {from, to} : null));
                            selection.hold(1);
                        }
                    }
                    case "jdk.GCPhasePause" -> {
                        long from = at(clock, e.getStartTime());
                        long to = at(clock, e.getEndTime());
                        if (selection.wanted(from, to)) {
                            phases.add(new Phase(e.getLong("gcId"), from, to, names.computeIfAbsent(e.getString("name"), k -> k)));
                            selection.hold(1);
                        } else {
                            selection.skip();
                        }
                    }
                    case "jdk.SafepointBegin" -> safepointSide(selection, openBegin, openEnd, true, e.getLong("safepointId"),
                            at(clock, e.getStartTime()), safepoints, vmOperations);
                    case "jdk.SafepointEnd" -> safepointSide(selection, openEnd, openBegin, false, e.getLong("safepointId"),
                            at(clock, e.getEndTime()), safepoints, vmOperations);
                    case "jdk.ExecuteVMOperation" -> {
                        long vs = at(clock, e.getStartTime());
                        // held when wanted, or while a safepoint is open: it may name a safepoint that is
                        if ((selection.wanted(vs, vs) || !openBegin.isEmpty() || !openEnd.isEmpty())
                                && !vmOperations.containsKey(vs)) {
                            vmOperations.put(vs, names.computeIfAbsent(e.getString("operation"), k -> k));
                            selection.hold(1);
                        }
                    }
                    case "jdk.Compilation" -> selection.add(new VmEvent(VmEventKind.COMPILATION,
                            at(clock, e.getStartTime()), at(clock, e.getEndTime()), threadName(e),
                            methodName(e.getValue("method")) + " level " + e.getValue("compileLevel")
                                    + (e.getBoolean("isOsr") ? " osr" : "")));
                    case "jdk.Deoptimization" -> selection.add(new VmEvent(VmEventKind.DEOPTIMIZATION,
                            at(clock, e.getStartTime()), at(clock, e.getEndTime()), threadName(e),
                            methodName(e.getValue("method")) + " " + e.getValue("reason")));
                    case "jdk.ClassLoad" -> selection.add(new VmEvent(VmEventKind.CLASS_LOAD,
                            at(clock, e.getStartTime()), at(clock, e.getEndTime()), threadName(e),
                            className(e)));
                    case "jdk.ThreadPark", "jdk.JavaMonitorEnter" -> selection.add(new VmEvent(VmEventKind.THREAD_BLOCKED,
                            at(clock, e.getStartTime()), at(clock, e.getEndTime()), threadName(e),
                            type.equals("jdk.ThreadPark") ? "park" : "monitor enter"));
                    default -> { }
                }
            }
        }

        Set<Long> pausedIds = new HashSet<>();
        for (Phase p : phases) {
            pausedIds.add(p.gcId());
            Collection c = collections.get(p.gcId());
            selection.add(new VmEvent(VmEventKind.GC_PAUSE, p.from(), p.to(), null,
                    (c != null ? c.name() : "GC") + " " + p.name() + " #" + p.gcId()));
        }
        // A collection recorded without its pause phases (phase events disabled, or an old JDK)
        // that paused for all of its duration is one pause.
        for (Map.Entry<Long, Collection> g : collections.entrySet()) {
            long[] whole = g.getValue().wholePause();
            if (!pausedIds.contains(g.getKey()) && whole != null) {
                selection.add(new VmEvent(VmEventKind.GC_PAUSE, whole[0], whole[1], null,
                        g.getValue().name() + " #" + g.getKey()));
            }
        }
        // a side never paired is a safepoint the recording stopped inside: left out
        for (long[] sp : safepoints) {
            String op = "safepoint #" + sp[0];
            Map.Entry<Long, String> v = vmOperations.ceilingEntry(sp[1]);
            if (v != null && v.getKey() <= sp[2]) {
                op = v.getValue() + " #" + sp[0];
            }
            selection.add(new VmEvent(VmEventKind.SAFEPOINT, sp[1], sp[2], null, op));
        }
    }

    /**
     * One side of a safepoint: held until its other side comes (either may come first), then the
     * safepoint kept for naming when it is wanted, else counted and the operations held only
     * because it was open let go.
     */
    private static void safepointSide(EventSelection selection, Map<Long, Long> mine, Map<Long, Long> other, boolean begin,
            long id, long at, List<long[]> safepoints, TreeMap<Long, String> vmOperations) throws IOException {
        Long o = other.remove(id);
        if (o == null) {
            if (mine.put(id, at) == null) {
                selection.hold(1);
            }
            return;
        }
        selection.hold(-1);
        long from = begin ? at : o;
        long to = Math.max(from, begin ? o : at);
        if (selection.wanted(from, to)) {
            safepoints.add(new long[] {id, from, to});
            selection.hold(1);
            return;
        }
        selection.skip();
        java.util.NavigableMap<Long, String> inside = vmOperations.subMap(from, true, to, true);
        int before = inside.size();
        inside.keySet().removeIf(vs -> !selection.wanted(vs, vs));
        selection.hold(inside.size() - before);
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
