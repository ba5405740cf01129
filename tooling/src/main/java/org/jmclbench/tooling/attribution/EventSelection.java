package org.jmclbench.tooling.attribution;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collections;
import java.util.Comparator;
import java.util.List;
import java.util.PriorityQueue;

/**
 * The runtime events a run's attribution keeps, chosen one by one while its recording or GC log is
 * read, so that a runtime that left gigabytes of events costs the harness no more memory than the
 * events it uses: those meeting a missed job's {@linkplain Attribution#windows window}, and the
 * {@link AttributionData#MAX_PAUSES} longest pauses of the run (the report's pause bands). The rest
 * are only counted. A reader also holds a few partial events (a safepoint's begin, a pause waiting
 * for its collection's name) through {@link #hold}, counted alike.
 *
 * <p>More than {@link #MAX_EVENTS} kept or held is refused (an IOException naming the file): such a
 * recording, of a runtime that did little but stop, is no evidence a harness can hold.
 */
public final class EventSelection {
    /** The most events kept or held at once (some 100 bytes each). */
    public static final int MAX_EVENTS = 500_000;

    private final Path source;
    private final List<long[]> windows;
    private final long runEndNs;
    private final int maxEvents;
    private final List<VmEvent> kept = new ArrayList<>();
    private final PriorityQueue<VmEvent> longestPauses = new PriorityQueue<>(Comparator.comparingLong(VmEvent::durationNs));
    private long read;
    private int held;

    EventSelection(Path source, List<long[]> windows, long runEndNs, int maxEvents) {
        this.source = source;
        this.windows = windows;
        this.runEndNs = runEndNs;
        this.maxEvents = maxEvents;
    }

    /** What the attribution of {@code jobs} uses, read from {@code source}. */
    public static EventSelection forJobs(Path source, List<JobRecord> jobs) {
        return new EventSelection(source, Attribution.windows(jobs), runEndNs(jobs), MAX_EVENTS);
    }

    /** Every event (the whole timeline is one window), up to {@link #MAX_EVENTS}. */
    public static EventSelection all(Path source) {
        return new EventSelection(source, List.of(new long[] {Long.MIN_VALUE, Long.MAX_VALUE}), Long.MAX_VALUE, MAX_EVENTS);
    }

    /** The end of the run: its last job's end or release; the pause bands reach no further. */
    static long runEndNs(List<JobRecord> jobs) {
        return jobs.stream().mapToLong(j -> Math.max(j.endNs(), j.releaseNs())).max().orElse(0);
    }

    /** Whether a pause from {@code startNs} to {@code endNs} is in the run, for its pause bands. */
    static boolean inRun(long startNs, long endNs, long runEndNs) {
        return endNs >= 0 && startNs <= runEndNs;
    }

    /** Whether [from, to] meets a window, or is in the run: worth holding while its event is incomplete. */
    public boolean wanted(long from, long to) {
        return meetsWindow(from, to) || inRun(from, to, runEndNs);
    }

    /** Takes one event read: kept when the attribution uses it, else counted. */
    public void add(VmEvent e) throws IOException {
        read++;
        if (meetsWindow(e.startNs(), e.endNs())) {
            kept.add(e);
            check();
        } else if ((e.kind() == VmEventKind.GC_PAUSE || e.kind() == VmEventKind.SAFEPOINT)
                && inRun(e.startNs(), e.endNs(), runEndNs)) {
            longestPauses.add(e);
            if (longestPauses.size() > AttributionData.MAX_PAUSES) {
                longestPauses.poll();
            }
        }
    }

    /** An event read and left out before it was put together (a pause phase or safepoint outside the run). */
    public void skip() {
        read++;
    }

    /** One more (or, negative, fewer) partial event held by the reader. */
    public void hold(int n) throws IOException {
        held += n;
        check();
    }

    /** How many events were read, kept or not. */
    public long read() {
        return read;
    }

    /** The events kept, sorted by start. */
    public List<VmEvent> events() {
        List<VmEvent> out = new ArrayList<>(kept);
        out.addAll(longestPauses);
        out.sort(Comparator.comparingLong(VmEvent::startNs));
        return Collections.unmodifiableList(out);
    }

    /** More events than the harness keeps: the file is no evidence it can use. */
    public static final class TooManyEvents extends IOException {
        private static final long serialVersionUID = 1L;

        TooManyEvents(String message) {
            super(message);
        }
    }

    private void check() throws TooManyEvents {
        if (kept.size() + held > maxEvents) {
            throw new TooManyEvents(source + ": more than " + maxEvents + " runtime events during the run's missed jobs"
                    + " (a runtime that did little but stop; its events are not read)");
        }
    }

    private boolean meetsWindow(long from, long to) {
        // disjoint and sorted, the windows end in order too: the last one starting by `to` is the only one to try
        int lo = 0;
        int hi = windows.size() - 1;
        int found = -1;
        while (lo <= hi) {
            int mid = (lo + hi) >>> 1;
            if (windows.get(mid)[0] <= to) {
                found = mid;
                lo = mid + 1;
            } else {
                hi = mid - 1;
            }
        }
        return found >= 0 && windows.get(found)[1] >= from;
    }
}
