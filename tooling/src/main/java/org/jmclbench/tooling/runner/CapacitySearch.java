package org.jmclbench.tooling.runner;

import java.util.ArrayList;
import java.util.List;
import java.util.function.IntPredicate;

/**
 * The search for one configuration's breakdown load (docs/RUNNER.md, "capacity"): the largest
 * particle count that holds (every job of both tasks done by its deadline in every repetition)
 * and the smallest that does not, bracketed to within {@link #TOLERANCE}.
 *
 * <p>Geometric first: from {@code from}, double while the count holds (the last step clamped to
 * {@code max}); then bisect the bracket at its geometric mean until {@code high <= low * 1.1}
 * (or the two are adjacent integers). Two ends have no bracket: the load fails already at
 * {@code from} ({@link Status#FAILS_AT_FROM}: high = from, no low), or it holds at {@code max}
 * ({@link Status#HOLDS_TO_MAX}: low = max, no high). Each count is probed once, so a noisy
 * outcome cannot make the search loop; the bracket is then one count that held and one that did
 * not, within 10%, which is what was measured. Driven one probe at a time ({@link #next},
 * {@link #record}) so that many searches can advance in lockstep.
 */
public final class CapacitySearch {
    /** The bracket's relative width at which the search stops: high <= low * (1 + TOLERANCE). */
    public static final double TOLERANCE = 0.10;

    /** How a finished search ended. */
    public enum Status {
        /** low held, high did not, high <= low * 1.1. */
        BRACKETED("bracketed"),
        /** The smallest count probed already failed. */
        FAILS_AT_FROM("fails-at-from"),
        /** Every count up to and including max held. */
        HOLDS_TO_MAX("holds-to-max");

        public final String label;

        Status(String label) {
            this.label = label;
        }
    }

    /**
     * One probed count and why it did not hold ({@code notHeld} null: it held); of its
     * {@code repetitions}, {@code held} completed with every job by its deadline (-1, -1: not told).
     */
    public record Probe(int particles, String notHeld, int held, int repetitions) {
        public Probe(int particles, String notHeld) {
            this(particles, notHeld, -1, -1);
        }
    }

    private final int from;
    private final int max;
    private Integer low;
    private Integer high;
    private final List<Probe> probes = new ArrayList<>();

    /** @throws IllegalArgumentException unless {@code 1 <= from <= max} */
    public CapacitySearch(int from, int max) {
        if (from < 1 || max < from) {
            throw new IllegalArgumentException("need 1 <= from <= max, got from " + from + ", max " + max);
        }
        this.from = from;
        this.max = max;
    }

    /** The next count to probe, or -1 when the search is done. */
    public int next() {
        if (low == null && high == null) {
            return from;
        }
        if (low == null) {
            return -1; // failed at from
        }
        if (high == null) {
            return low == max ? -1 : (int) Math.min(max, 2L * low);
        }
        if (high - low <= 1 || high <= low * (1 + TOLERANCE)) {
            return -1;
        }
        long mid = Math.round(Math.sqrt((double) low * high));
        return (int) Math.max(low + 1, Math.min(high - 1, mid));
    }

    /**
     * Records the outcome of probing {@code particles}, which must be {@link #next()}: null when
     * it held, else why not, in a few words.
     *
     * @throws IllegalStateException for a count the search did not ask for
     */
    public void record(int particles, String notHeld) {
        record(new Probe(particles, notHeld));
    }

    /** {@link #record(int, String)} with how many of the count's repetitions held. */
    public void record(Probe probe) {
        int particles = probe.particles();
        String notHeld = probe.notHeld();
        int expected = next();
        if (particles != expected) {
            throw new IllegalStateException("probed " + particles + ", the search asked for " + expected);
        }
        probes.add(probe);
        if (notHeld == null) {
            low = particles;
        } else {
            high = particles;
        }
    }

    public boolean done() {
        return next() < 0;
    }

    /** The largest count that held (null: none did). */
    public Integer low() {
        return low;
    }

    /** The smallest count that did not hold (null: every probe held). */
    public Integer high() {
        return high;
    }

    /** Why {@link #high()} did not hold (null: no count failed). */
    public String highNotHeld() {
        return probes.stream().filter(p -> high != null && p.particles() == high).map(Probe::notHeld).findFirst().orElse(null);
    }

    public List<Probe> probes() {
        return List.copyOf(probes);
    }

    /**
     * The counts above {@link #high()} at which some repetition held, in increasing order: the
     * outcome is not monotone in the load there (a noisy machine), so the bracket is as uncertain as
     * those runs and a repeated search may place it elsewhere, even further than a step.
     */
    public List<Probe> heldAboveHigh() {
        return probes.stream().filter(p -> high != null && p.particles() > high && p.held() > 0)
                .sorted(java.util.Comparator.comparingInt(Probe::particles)).toList();
    }

    /** How the search ended; null while it runs. */
    public Status status() {
        if (!done()) {
            return null;
        }
        return low == null ? Status.FAILS_AT_FROM : high == null ? Status.HOLDS_TO_MAX : Status.BRACKETED;
    }

    /**
     * The most probes a search from {@code from} to {@code max} can take: the doublings, then the
     * bisections of a factor-2 bracket down to 10% (for progress: an upper bound of the work left).
     */
    public static int maxProbes(int from, int max) {
        int doublings = 1;
        for (long n = from; n < max; n *= 2) {
            doublings++;
        }
        int bisections = 0;
        for (double w = Math.log(2); w > Math.log(1 + TOLERANCE); w /= 2) {
            bisections++;
        }
        return doublings + bisections;
    }

    /** Runs a whole search against an outcome function (for tests and single searches). */
    public static CapacitySearch run(int from, int max, IntPredicate holds) {
        CapacitySearch s = new CapacitySearch(from, max);
        for (int n = s.next(); n >= 0; n = s.next()) {
            s.record(n, holds.test(n) ? null : "failed");
        }
        return s;
    }
}
