package org.jmclbench.tooling.report;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import com.fasterxml.jackson.databind.JsonNode;

import org.jmclbench.tooling.cli.JsonFiles;

/**
 * The static side of termination (issue 19): for each engine's job and memory style, the longest
 * path between two points where an abort takes effect, in particle steps, as {@code ./jmclbench
 * verify} found it in the bytecode and wrote it into {@code verification.json}. With a cell's
 * measured cost of a particle step it becomes a bound in time, drawn beside the measured abort
 * latency. No bound is known for the C baseline (no bytecode) or without a verification file.
 */
public final class AbortBounds {
    /** No verification file: no bound is drawn. */
    public static final AbortBounds NONE = new AbortBounds(List.of());

    /**
     * One job's bound.
     *
     * @param engine   the engine as the store names it ({@code rtsj}: the thesis design, {@code rtsj-atomic})
     * @param memory   the memory style
     * @param steps    particle steps between two abort points, or null: nothing bounds the gap, so
     *                 an abort waits for the job's end
     * @param at       where the longest gap is ({@code Class.method:line})
     */
    public record Bound(String engine, String memory, Long steps, String at) {
        /** True when an abort can wait for the job's end. */
        public boolean wholeJob() {
            return steps == null;
        }

        /**
         * The bound in ms at a cell's load: the steps times the cell's costliest particle step (the
         * slowest job of either task over its particles: a job's loops together cost that per
         * particle, so one step of any loop costs no more), or the slowest job itself when the
         * whole job bounds it; null when the cell completed no job.
         */
        public Double millis(ReportModel.Cell c) {
            double slowest = 0;
            double step = 0;
            for (String task : List.of("predict", "update")) {
                ReportModel.Agg a = c.metrics.get(TaskMetric.LATENCY_MAX.key(task));
                if (a != null && a.max() != null && Double.isFinite(a.max())) {
                    slowest = Math.max(slowest, a.max());
                    step = Math.max(step, a.max() / c.particles);
                }
            }
            if (slowest <= 0) {
                return null;
            }
            return wholeJob() ? slowest : steps * step;
        }

        /** "64 steps" or "the whole job", for tables and legends. */
        public String span() {
            return wholeJob() ? "the whole job" : steps + " particle steps";
        }
    }

    private final List<Bound> bounds;

    private AbortBounds(List<Bound> bounds) {
        this.bounds = List.copyOf(bounds);
    }

    /**
     * The bounds in {@code verification}, or {@link #NONE} when the file does not exist or predates them.
     *
     * @throws org.jmclbench.tooling.cli.BadUsageException one line naming the file (and line) when it is not a JSON object
     */
    public static AbortBounds read(Path verification) {
        if (verification == null || !Files.isRegularFile(verification)) {
            return NONE;
        }
        List<Bound> bounds = new ArrayList<>();
        for (JsonNode b : JsonFiles.readObject(verification, null).path("abortBounds")) {
            JsonNode steps = b.path("steps");
            bounds.add(new Bound(b.path("engine").asText(), b.path("memory").asText(),
                    steps.isNumber() ? steps.asLong() : null, b.path("at").asText(null)));
        }
        return new AbortBounds(bounds);
    }

    /** The bound of a cell's job, or null: the C baseline, or an engine verify did not analyse. */
    public Bound of(ReportModel.Cell c, ReportModel model) {
        boolean bytecode = model.configs.stream().noneMatch(i -> i.id().equals(c.config)
                && i.kind() == org.jmclbench.tooling.runtime.RuntimeKind.NATIVE);
        if (!bytecode) {
            return null;
        }
        return bounds.stream().filter(b -> b.engine().equals(c.engine) && b.memory().equals(c.memory)).findFirst().orElse(null);
    }
}
