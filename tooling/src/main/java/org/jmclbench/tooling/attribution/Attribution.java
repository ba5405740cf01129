package org.jmclbench.tooling.attribution;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;

/**
 * Says why each missed or late job of a run missed: the runtime's events ({@link VmEvent}s from
 * JFR or the GC log) that overlap the job's window, and what its own timestamps show.
 *
 * <p>The window of a late or terminated job runs from its release to its end. A skipped job
 * never ran: it was released while another job held the robot (from that job's release to
 * its end, as the release engine takes the robot at release), so its causes are those of
 * that blocking job, over the blocking job's window from its release to its end (an event
 * that delayed the blocker before this release delayed this job too).
 *
 * <p>Causes are listed largest first, except {@code jit} and {@code deopt}, listed last; the
 * first is the job's primary cause.
 *
 * <p>Causes, each with the time it accounts for:
 * <ul>
 * <li>{@code gc}: stop-the-world GC pauses inside the window;</li>
 * <li>{@code safepoint}: safepoints inside the window, less their GC part;</li>
 * <li>{@code jit} / {@code deopt}: compilation or deoptimisation of the job's own code
 *     (methods under {@link Settings#jobCodePrefix}) during the window;</li>
 * <li>{@code classload} / {@code lock}: class loading or parking/monitor waits of the job's
 *     own handler thread (its name contains the task name) while the job ran, less the pauses
 *     during it (those are {@code gc} or {@code safepoint}, not counted twice);</li>
 * <li>{@code queued}: the job started late because another job held the robot: the time that
 *     job worked (a pause during it is {@code gc} or {@code safepoint}, not counted twice);</li>
 * <li>{@code os}: the job started late and nothing above explains it: the dispatcher or
 *     the handler woke late (the operating system's scheduling);</li>
 * <li>{@code preemption}: the job's wall time is well above its CPU time and pauses and
 *     waits do not explain the difference: its thread was runnable but not running;</li>
 * <li>{@code compute}: the job's CPU time alone exceeds its relative deadline (for a skipped
 *     job: the blocker's CPU time alone, from its own release, reaches past this release);</li>
 * <li>{@code overlap}: a skipped job whose blocker ran normally: the two events came closer
 *     together than the blocker's ordinary response time (no anomaly: the timeline's own collision);
 *     or a terminated job superseded by the next release before its handler started it, over the
 *     window between the two releases; or one aborted by it while it ran normally (nothing else
 *     found), over its window;</li>
 * <li>{@code unknown}: none of these.</li>
 * </ul>
 * Without runtime events (the C baseline, or a JVM run without capture) only
 * {@code queued}, {@code os}, {@code preemption} and {@code compute} can be found.
 */
public final class Attribution {

    /**
     * Thresholds of the attribution.
     *
     * @param osThresholdNs   a start delay below this is not a cause (default 1 ms)
     * @param minOverlapNs    a runtime event overlapping less than this is not a cause (default 100 us)
     * @param preemptionRatio wall time must exceed CPU time by this factor ... (default 1.5)
     * @param preemptionMinNs ... and by this much, after pauses and waits (default 1 ms)
     * @param jobCodePrefix   the job's own code, for {@code jit} and {@code deopt}
     */
    public record Settings(long osThresholdNs, long minOverlapNs, double preemptionRatio, long preemptionMinNs,
            String jobCodePrefix) {

        /** The defaults quoted above. */
        public static Settings defaults() {
            return new Settings(1_000_000L, 100_000L, 1.5, 1_000_000L, "org.jmclbench.core.");
        }
    }

    private final List<JobRecord> started;
    private final List<JobRecord> byRelease;
    private final List<VmEvent> events;
    private final List<long[]> gcUnion;
    private final List<long[]> stwUnion;
    private final Settings settings;

    private Attribution(List<JobRecord> jobs, List<VmEvent> events, Settings settings) {
        this.settings = settings;
        this.events = events;
        this.started = jobs.stream().filter(JobRecord::started).sorted(Comparator.comparingLong(JobRecord::startNs)).toList();
        this.byRelease = jobs.stream().sorted(Comparator.comparingLong(JobRecord::releaseNs)).toList();
        this.gcUnion = union(events.stream().filter(e -> e.kind() == VmEventKind.GC_PAUSE).toList());
        this.stwUnion = union(events.stream()
                .filter(Attribution::stopsTheWorld).toList());
    }

    /** The causes of every missed or late job of {@code jobs} (all tasks of one run), in task then index order. */
    public static List<JobAttribution> attribute(List<JobRecord> jobs, List<VmEvent> events, Settings settings) {
        Attribution a = new Attribution(jobs, events, settings);
        List<JobAttribution> out = new ArrayList<>();
        jobs.stream().filter(JobRecord::missedOrLate)
                .sorted(Comparator.comparing(JobRecord::task).thenComparingInt(JobRecord::index))
                .forEach(j -> out.add(a.explain(j)));
        return out;
    }

    /**
     * The stretches of the run whose runtime events the attribution of {@code jobs} reads: disjoint,
     * sorted [start, end] pairs covering every missed or late job's window, its start delay and run,
     * and those of the job that blocked it. An event that meets none of them changes no attribution.
     */
    public static List<long[]> windows(List<JobRecord> jobs) {
        Attribution a = new Attribution(jobs, List.of(), Settings.defaults());
        List<VmEvent> spans = new ArrayList<>();
        for (JobRecord j : jobs) {
            if (!j.missedOrLate()) {
                continue;
            }
            JobRecord b = j.started() ? null : a.blocker(j);
            JobRecord s = a.supersededBy(j);
            long from = b != null ? Math.min(b.releaseNs(), j.releaseNs()) : j.releaseNs();
            long to = Math.max(Math.max(j.releaseNs(), j.deadlineNs()), Math.max(j.startNs(), j.endNs()));
            if (b != null) {
                to = Math.max(to, Math.max(b.startNs(), b.endNs()));
            }
            if (s != null) {
                to = Math.max(to, s.releaseNs());
            }
            spans.add(new VmEvent(VmEventKind.SAFEPOINT, from, to, null, ""));
        }
        return union(spans);
    }

    /** How many jobs have each cause kind (a job counts once per kind), sorted by kind. */
    public static Map<String, Integer> countCauses(List<JobAttribution> attributions) {
        Map<String, Integer> counts = new TreeMap<>();
        for (JobAttribution a : attributions) {
            a.causes().stream().map(Cause::kind).distinct().forEach(k -> counts.merge(k, 1, Integer::sum));
        }
        return counts;
    }

    /** How many jobs have each kind as their primary (largest) cause, sorted by kind: a partition of the jobs. */
    public static Map<String, Integer> countPrimaryCauses(List<JobAttribution> attributions) {
        Map<String, Integer> counts = new TreeMap<>();
        for (JobAttribution a : attributions) {
            counts.merge(a.primary().kind(), 1, Integer::sum);
        }
        return counts;
    }

    private JobAttribution explain(JobRecord j) {
        List<Cause> causes = new ArrayList<>();
        long ws;
        long we;
        String blockedBy = null;
        if (!j.started()) {
            JobRecord b = blocker(j);
            if (b != null) {
                blockedBy = b.task() + "#" + b.index();
                ws = b.releaseNs();
                we = b.endNs() >= 0 ? Math.max(b.endNs(), j.releaseNs()) : j.releaseNs();
                startDelayCauses(b, causes);
                runCauses(b, ws, we, causes);
                // Plain compute: started at its own release and never interrupted, the blocker
                // would still have held the robot at this release.
                if (b.cpuNs() >= 0 && b.releaseNs() + b.cpuNs() > j.releaseNs()) {
                    causes.add(new Cause("compute", b.cpuNs(), String.format(Locale.ROOT,
                            "the blocking job %s needs %s of CPU, past this release", blockedBy, ms(b.cpuNs()))));
                }
                if (causes.isEmpty()) {
                    // Nothing went wrong with the blocker: the two events came closer together than
                    // its ordinary response time (release jitter below the thresholds plus compute).
                    causes.add(new Cause("overlap", we - j.releaseNs(), String.format(Locale.ROOT,
                            "released %s after %s, which ran normally (response %s)", ms(j.releaseNs() - b.releaseNs()),
                            blockedBy, ms(b.endNs() - b.releaseNs()))));
                }
            } else {
                // terminate: the next release may have come before the job's handler started it
                JobRecord s = supersededBy(j);
                ws = j.releaseNs();
                we = s != null ? s.releaseNs() : j.deadlineNs() >= 0 ? j.deadlineNs() : j.releaseNs();
                vmCauses(null, ws, we, causes);
                if (s != null && causes.isEmpty()) {
                    causes.add(new Cause("overlap", we - ws, String.format(Locale.ROOT,
                            "superseded by %s#%d, released %s later, before its handler started it", s.task(), s.index(),
                            ms(we - ws))));
                }
            }
        } else {
            ws = j.releaseNs();
            we = j.endNs() >= 0 ? j.endNs() : Math.max(ws, j.deadlineNs());
            startDelayCauses(j, causes);
            runCauses(j, ws, we, causes);
            long relativeDeadline = j.deadlineNs() - j.releaseNs();
            if (j.cpuNs() >= 0 && j.deadlineNs() >= 0 && j.cpuNs() > relativeDeadline) {
                causes.add(new Cause("compute", j.cpuNs(), String.format(Locale.ROOT,
                        "%s of CPU for a %s deadline", ms(j.cpuNs()), ms(relativeDeadline))));
            }
            JobRecord s = supersededBy(j);
            if (s != null && causes.isEmpty()) {
                // terminate aborted a job that ran normally: the next release came before its ordinary response time
                causes.add(new Cause("overlap", we - ws, String.format(Locale.ROOT,
                        "superseded by %s#%d, released %s later, while it ran normally", s.task(), s.index(),
                        ms(s.releaseNs() - j.releaseNs()))));
            }
        }
        if (causes.isEmpty()) {
            causes.add(new Cause("unknown", we - ws, ""));
        }
        // jit and deopt last: their time is a compilation's overlap with the window, during
        // which the job ran slower code, not time during which it stood still.
        causes.sort(Comparator.comparingInt((Cause c) -> c.kind().equals("jit") || c.kind().equals("deopt") ? 1 : 0)
                .thenComparing(Comparator.comparingLong(Cause::ns).reversed()));
        return new JobAttribution(j.task(), j.index(), j.outcome(), ws, we, blockedBy, List.copyOf(causes));
    }

    /**
     * The job that held the robot when {@code j} was released: the latest one released before
     * it that had not yet ended (the release engine takes the robot for a job at its release,
     * so a job released but not yet started holds it too).
     */
    private JobRecord blocker(JobRecord j) {
        JobRecord found = null;
        for (JobRecord b : byRelease) {
            if (b.releaseNs() > j.releaseNs()) {
                break;
            }
            if (b != j && b.started() && (b.endNs() < 0 || b.endNs() > j.releaseNs())
                    && (found == null || b.releaseNs() >= found.releaseNs())) {
                found = b;
            }
        }
        return found;
    }

    /**
     * The release that superseded a terminated job before it started: the first job released
     * after it, by its deadline; null for a job of any other outcome, or when there is none.
     */
    private JobRecord supersededBy(JobRecord j) {
        if (!j.outcome().equals("terminated")) {
            return null;
        }
        for (JobRecord b : byRelease) {
            if (b.releaseNs() > j.releaseNs()) {
                return j.deadlineNs() < 0 || b.releaseNs() <= j.deadlineNs() ? b : null;
            }
        }
        return null;
    }

    /** {@code queued} and {@code os}: why a job that ran started late. */
    private void startDelayCauses(JobRecord j, List<Cause> causes) {
        long delay = j.startNs() - j.releaseNs();
        if (delay <= settings.osThresholdNs()) {
            return;
        }
        long busy = 0;
        Set<String> holders = new LinkedHashSet<>();
        for (JobRecord b : started) {
            if (b.startNs() >= j.startNs()) {
                break;
            }
            long end = b.endNs() >= 0 ? b.endNs() : b.startNs();
            long from = Math.max(b.startNs(), j.releaseNs());
            long to = Math.min(end, j.startNs());
            // a pause while the other job ran is counted once, as gc or safepoint (below, and in
            // vmCauses): counted here too, it hid as much of an OS delay and overfilled the window
            long o = Math.max(0, to - from) - overlap(stwUnion, from, to);
            if (b != j && o > 0) {
                busy += o;
                holders.add(b.task() + "#" + b.index());
            }
        }
        if (busy >= settings.osThresholdNs()) {
            causes.add(new Cause("queued", busy, "waited for " + limit(holders)));
        }
        long rest = delay - busy - overlap(stwUnion, j.releaseNs(), j.startNs());
        if (rest > settings.osThresholdNs()) {
            causes.add(new Cause("os", rest, "started " + ms(delay) + " after its release, " + ms(rest) + " not explained by other jobs or pauses"));
        }
    }

    /** Runtime events and preemption over the window of a job that ran. */
    private void runCauses(JobRecord job, long ws, long we, List<Cause> causes) {
        vmCauses(job, ws, we, causes);
        if (job.cpuNs() >= 0 && job.endNs() >= 0) {
            long wall = job.endNs() - job.startNs();
            // pauses and waits once each: a wait during a pause is not taken out twice
            long stoppedOrWaiting = overlap(union(events.stream().filter(e -> stopsTheWorld(e)
                    || e.kind() == VmEventKind.THREAD_BLOCKED && onThreadOf(e, job)).toList()), job.startNs(), job.endNs());
            long offCpu = wall - job.cpuNs() - stoppedOrWaiting;
            if (offCpu > settings.preemptionMinNs() && wall > settings.preemptionRatio() * job.cpuNs()) {
                causes.add(new Cause("preemption", offCpu, String.format(Locale.ROOT,
                        "%s#%d ran %s for %s of CPU", job.task(), job.index(), ms(wall), ms(job.cpuNs()))));
            }
        }
    }

    /** GC pauses, safepoints, JIT, class loading and waits over a window ({@code job} null: no thread-bound causes). */
    private void vmCauses(JobRecord job, long ws, long we, List<Cause> causes) {
        long gc = overlap(gcUnion, ws, we);
        if (gc >= settings.minOverlapNs()) {
            causes.add(new Cause("gc", gc, describe(VmEventKind.GC_PAUSE, ws, we, null, null)));
        }
        long safepoint = overlap(stwUnion, ws, we) - gc;
        if (safepoint >= settings.minOverlapNs()) {
            causes.add(new Cause("safepoint", safepoint, describe(VmEventKind.SAFEPOINT, ws, we, null, null)));
        }
        String prefix = settings.jobCodePrefix();
        List<VmEvent> jit = events.stream().filter(e -> e.kind() == VmEventKind.COMPILATION
                && e.detail().startsWith(prefix) && e.meets(ws, we)).toList();
        if (!jit.isEmpty()) {
            causes.add(new Cause("jit", overlap(union(jit), ws, we), describe(VmEventKind.COMPILATION, ws, we, prefix, null)));
        }
        List<VmEvent> deopt = events.stream().filter(e -> e.kind() == VmEventKind.DEOPTIMIZATION
                && e.detail().startsWith(prefix) && e.meets(ws, we)).toList();
        if (!deopt.isEmpty()) {
            causes.add(new Cause("deopt", 0, describe(VmEventKind.DEOPTIMIZATION, ws, we, prefix, null)));
        }
        if (job != null && job.endNs() >= 0) {
            for (VmEventKind k : List.of(VmEventKind.CLASS_LOAD, VmEventKind.THREAD_BLOCKED)) {
                // a pause while the thread loaded or waited is counted once, as gc or safepoint: counted
                // here too, it filled the window twice (with compute, more than the window)
                long ns = overlap(union(events.stream().filter(e -> stopsTheWorld(e) || e.kind() == k && onThreadOf(e, job))
                        .toList()), job.startNs(), job.endNs()) - overlap(stwUnion, job.startNs(), job.endNs());
                if (ns >= settings.minOverlapNs()) {
                    causes.add(new Cause(k.cause(), ns, describe(k, job.startNs(), job.endNs(), null, job)));
                }
            }
        }
    }

    private static boolean stopsTheWorld(VmEvent e) {
        return e.kind() == VmEventKind.GC_PAUSE || e.kind() == VmEventKind.SAFEPOINT;
    }

    private static boolean onThreadOf(VmEvent e, JobRecord job) {
        return e.thread() != null && e.thread().toLowerCase(Locale.ROOT).contains(job.task().toLowerCase(Locale.ROOT));
    }

    /** The largest few events of a kind in the window, e.g. {@code DefNew (Allocation Failure) GC Pause #3 12.3 ms}. */
    private String describe(VmEventKind kind, long ws, long we, String prefix, JobRecord job) {
        List<VmEvent> in = events.stream().filter(e -> e.kind() == kind && e.meets(ws, we)
                && (prefix == null || e.detail().startsWith(prefix)) && (job == null || onThreadOf(e, job)))
                .sorted(Comparator.comparingLong(VmEvent::durationNs).reversed()).toList();
        Set<String> parts = new LinkedHashSet<>();
        for (VmEvent e : in) {
            parts.add(kind == VmEventKind.DEOPTIMIZATION || kind == VmEventKind.COMPILATION
                    ? e.detail() : e.detail() + " " + ms(e.durationNs()));
        }
        return limit(parts);
    }

    private static String limit(Set<String> parts) {
        List<String> l = new ArrayList<>(parts);
        String s = String.join("; ", l.subList(0, Math.min(3, l.size())));
        return l.size() > 3 ? s + "; and " + (l.size() - 3) + " more" : s;
    }

    static String ms(long ns) {
        return String.format(Locale.ROOT, "%.3f ms", ns / 1e6);
    }

    /** Merges intervals into a sorted list of disjoint [start, end] pairs. */
    static List<long[]> union(List<VmEvent> in) {
        List<VmEvent> sorted = in.stream().sorted(Comparator.comparingLong(VmEvent::startNs)).toList();
        List<long[]> out = new ArrayList<>();
        for (VmEvent e : sorted) {
            long[] last = out.isEmpty() ? null : out.get(out.size() - 1);
            if (last != null && e.startNs() <= last[1]) {
                last[1] = Math.max(last[1], e.endNs());
            } else {
                out.add(new long[] {e.startNs(), e.endNs()});
            }
        }
        return out;
    }

    /** Total length of the part of [from, to] covered by disjoint intervals. */
    static long overlap(List<long[]> disjoint, long from, long to) {
        long sum = 0;
        for (long[] iv : disjoint) {
            sum += Math.max(0, Math.min(iv[1], to) - Math.max(iv[0], from));
        }
        return sum;
    }
}
