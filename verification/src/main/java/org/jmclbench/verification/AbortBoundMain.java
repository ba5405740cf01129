package org.jmclbench.verification;

import java.io.IOException;
import java.io.PrintStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.TreeMap;

import org.jmclbench.core.mcl.MotionModel;
import org.jmclbench.verification.bytecode.AbortBound;
import org.jmclbench.verification.bytecode.AbortPollCheck;
import org.jmclbench.verification.bytecode.ClassPool;
import org.jmclbench.workload.BadInputException;
import org.jmclbench.workload.RunOptionsParser;
import org.objectweb.asm.tree.ClassNode;
import org.objectweb.asm.tree.MethodNode;

import com.fasterxml.jackson.core.JsonLocation;
import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;

import picocli.CommandLine.Command;
import picocli.CommandLine.Option;

/**
 * {@code ./jmclbench abort-bound}: the static bound on abort latency of an engine's terminable
 * job ({@link AbortBound}) and, with a run folder, the bound in time beside the measured
 * distribution: a particle step costs at most the run's task latency divided by its particles
 * (a job's loops together cost that per particle), so a gap of G steps takes at most G times it.
 */
@Command(sortOptions = false, description = "The static bound on abort latency of an engine's"
        + " terminable job and, with --run, that bound in time beside the run's measured abort latency.",
        footer = "With --run, the options left out are the run's.")
public final class AbortBoundMain {
    /** The localizer of each memory style: the job runs one, so the others' loops are not its code. */
    private static final Map<String, String> LOCALIZERS = Map.of("preallocated", "org/jmclbench/core/mcl/PreallocatedLocalizer",
            "scoped", "org/jmclbench/core/mcl/ScopedLocalizer", "allocating", "org/jmclbench/workload/mcl/AllocatingLocalizer");

    @Option(names = "--engine", paramLabel = "javase|scj|hvm|rtsj", description = "whose job")
    private String engine;
    @Option(names = "--rtsj-design", paramLabel = "thesis|atomic", description = "the rtsj engine's design (default thesis)")
    private String design;
    @Option(names = "--memory", paramLabel = "preallocated|allocating|scoped",
            description = "the memory style, whose localizer the job runs (default preallocated)")
    private String memory;
    @Option(names = "--classes", paramLabel = "JAR_OR_DIR[:...]", description = "the workload jar (the launcher gives it)")
    private String classes;
    @Option(names = "--run", paramLabel = "RUN_FOLDER", description = "a run of that job: the bound in time beside its"
            + " measured abort latency")
    private Path runDir;
    @Option(names = {"-h", "--help"}, usageHelp = true, description = "this help")
    private boolean help;

    /** An engine's job: where it starts and how an abort takes effect. */
    private record Job(String[][] entries, AbortBound.Mode mode) {
    }

    private AbortBoundMain() {
    }

    public static void main(String[] args) {
        System.exit(run(args, System.out, System.err));
    }

    /** Runs the command; 0, or 2 with one line on {@code err} for bad input. */
    static int run(String[] args, PrintStream out, PrintStream err) {
        AbortBoundMain options = new AbortBoundMain();
        Integer exit = CommandLines.parse(options, "abort-bound", args, out, err);
        return exit != null ? exit : options.bound(out, err);
    }

    private int bound(PrintStream out, PrintStream err) {
        String engine = this.engine;
        String design = this.design;
        String memory = this.memory;
        JsonNode summary = null;
        if (runDir != null) {
            Path s = runDir.resolve("summary.json");
            try {
                long size = Files.size(s);
                if (size > MAX_SUMMARY_BYTES) {
                    // read whole, a runaway one would end this tool with OutOfMemoryError
                    return bad(err, "--run: " + s + ": not a run's summary.json (" + size + " bytes, more than "
                            + MAX_SUMMARY_BYTES + ")");
                }
                summary = new ObjectMapper().readTree(Files.readString(s));
            } catch (JsonProcessingException e) {
                // Jackson's message puts the source and location on lines of their own
                JsonLocation at = e.getLocation();
                return bad(err, "--run: " + s + (at != null && at.getLineNr() > 0 ? ":" + at.getLineNr() : "")
                        + ": not JSON (" + e.getOriginalMessage().replaceAll("\\s+", " ").strip() + ")");
            } catch (IOException e) {
                return bad(err, "--run: cannot read " + s + ": " + e.getMessage());
            }
            if (summary == null || !summary.isObject()) {
                return bad(err, "--run: " + s + ": not a run's summary.json (no JSON object)");
            }
            // the run says what ran: an option left out is taken from it, one that contradicts it is an error
            JsonNode ran = summary.path("parameters");
            String[][] taken = {{"--engine", engine, ran.path("engine").asText(null)},
                    {"--rtsj-design", design, ran.path("rtsjDesign").asText(null)},
                    {"--memory", memory, ran.path("memory").asText(null)}};
            for (String[] t : taken) {
                if (t[1] != null && t[2] != null && !t[1].equals(t[2])) {
                    return bad(err, t[0] + ": '" + t[1] + "', but the run in " + runDir + " used '" + t[2] + "'");
                }
            }
            engine = engine != null ? engine : taken[0][2];
            design = design != null ? design : taken[1][2];
            memory = memory != null ? memory : taken[2][2];
        }
        design = design != null ? design : "thesis";
        memory = memory != null ? memory : "preallocated";
        if (engine == null) {
            return bad(err, "--engine: required (or --run)");
        }
        if (!design.equals("thesis") && !design.equals("atomic")) {
            return bad(err, "--rtsj-design: '" + design + "' is not one of thesis|atomic");
        }
        if (!LOCALIZERS.containsKey(memory)) {
            return bad(err, "--memory: '" + memory + "' is not one of preallocated|allocating|scoped");
        }
        String localizer = LOCALIZERS.get(memory);
        Job job = job(engine);
        if (job == null) {
            return bad(err, "--engine: '" + engine + "' is not one of javase|scj|hvm|rtsj"
                    + (engine.equals("native") ? " (the C baseline has no bytecode to analyse)" : ""));
        }
        String unrunnable = unrunnable(engine, memory, this.design != null ? design : null);
        if (unrunnable != null) {
            return bad(err, unrunnable);
        }
        if (classes == null) {
            return bad(err, "--classes: required (the workload jar)");
        }
        try {
            List<Path> paths = new ArrayList<>();
            for (String p : classes.split(":")) {
                if (!Files.exists(Paths.get(p))) {
                    return bad(err, "--classes: no such file or folder: " + p);
                }
                paths.add(Paths.get(p));
            }
            ClassPool pool = ClassPool.of(paths);
            List<ClassPool.Owned> entries = entries(pool, job);
            if (entries == null) {
                return bad(err, "--classes: " + classes + " has no " + String.join(" or ", Arrays.stream(job.entries())
                        .map(e -> e[0].replace('/', '.') + "." + e[1]).toList()) + " (not the workload jar?)");
            }
            AbortBound.Result r = analyse(pool, job, entries, design, localizer);
            report(out, engine + (engine.equals("rtsj") ? " " + design : "") + ", memory " + memory, job, entries, r, summary);
            return 0;
        } catch (IOException e) {
            return bad(err, "--classes: cannot read " + classes + ": " + e.getMessage());
        }
    }

    /**
     * The workload's own refusal of an engine, memory style and design that no run has (the rtsj
     * engine's scoped style, a design without the rtsj engine), or null: no job to bound. The hvm
     * runs the scj engine's mission, so it has the scj engine's styles.
     */
    private static String unrunnable(String engine, String memory, String design) {
        List<String> line = new ArrayList<>(List.of("--engine", engine.equals("hvm") ? "scj" : engine, "--memory", memory));
        if (design != null) {
            line.addAll(List.of("--rtsj-design", design));
        }
        try {
            RunOptionsParser.parse(line.toArray(new String[0]));
            return null;
        } catch (BadInputException e) {
            return engine.equals("hvm") ? e.getMessage().replace("the scj engine", "the SCJ mission the hvm runs") : e.getMessage();
        }
    }

    private static Job job(String engine) {
        return switch (engine) {
            case "javase" -> new Job(new String[][] {{"org/jmclbench/workload/release/LocalizerJob", "run", "AbortSignal;)Z"}},
                    AbortBound.Mode.COOPERATIVE);
            case "scj", "hvm" -> new Job(new String[][] {{"org/jmclbench/scj/Robot", "predict", "AbortSignal;)Z"},
                    {"org/jmclbench/scj/Robot", "update", "AbortSignal;)Z"}}, AbortBound.Mode.COOPERATIVE);
            case "rtsj" -> new Job(new String[][] {{"org/jmclbench/workload/rtsj/RtsjReplay$Task", "run",
                    "AsynchronouslyInterruptedException;)V"}}, AbortBound.Mode.ATC);
            default -> null;
        };
    }

    /** The job's entry methods in the pool, or null when one is missing. */
    private static List<ClassPool.Owned> entries(ClassPool pool, Job job) {
        List<ClassPool.Owned> entries = new ArrayList<>();
        for (String[] e : job.entries()) {
            ClassPool.Owned m = method(pool, e[0], e[1], e[2]);
            if (m == null) {
                return null;
            }
            entries.add(m);
        }
        return entries;
    }

    private static AbortBound.Result analyse(ClassPool pool, Job job, List<ClassPool.Owned> entries, String design, String localizer) {
        Map<String, String> known = Map.of("org/jmclbench/workload/rtsj/RtsjDesign", design.toUpperCase(Locale.ROOT));
        // the shipped job only: verify's pool also holds verification's own subclasses (CheckedRobot), which no run executes
        return new AbortBound(pool, n -> n.startsWith("org/jmclbench/") && !n.startsWith("org/jmclbench/rtsjcompat/")
                && !n.startsWith("org/jmclbench/verification/")
                && (n.equals(localizer) || !LOCALIZERS.containsValue(n)), MotionModel.ABORT_BLOCK, job.mode(), known)
                .analyse(entries);
    }

    /**
     * The static bound of every engine's job in every memory style, as the store names engines
     * ({@code rtsj} is the thesis design, {@code rtsj-atomic} the atomic one; the hvm compiles the
     * scj engine's job, loops and polls as they are): what {@code verify} writes into
     * verification.json for the report to draw beside the measured abort latency. Jobs whose
     * classes the pool lacks are left out.
     */
    static List<Map<String, Object>> allBounds(ClassPool pool) {
        List<Map<String, Object>> bounds = new ArrayList<>();
        for (String engine : List.of("javase", "scj", "hvm", "rtsj", "rtsj-atomic")) {
            Job job = job(engine.startsWith("rtsj") ? "rtsj" : engine);
            List<ClassPool.Owned> entries = entries(pool, job);
            if (entries == null) {
                continue;
            }
            for (Map.Entry<String, String> style : new TreeMap<>(LOCALIZERS).entrySet()) {
                if (pool.get(style.getValue()) == null) {
                    continue;
                }
                AbortBound.Result r = analyse(pool, job, entries, engine.equals("rtsj-atomic") ? "atomic" : "thesis", style.getValue());
                Map<String, Object> b = new LinkedHashMap<>();
                b.put("engine", engine);
                b.put("memory", style.getKey());
                long steps = r.longestSteps();
                boolean whole = r.wholeJob() || steps == AbortPollCheck.UNKNOWN;
                // null: no abort point bounds the gap, so an abort waits for the job's end
                b.put("steps", whole ? null : steps);
                b.put("bytecodes", whole ? null : r.longestBytecodes());
                b.put("wholeJob", r.wholeJob());
                b.put("at", r.longest() == null ? null : r.longest().where());
                b.put("deferrals", r.deferrals());
                bounds.add(b);
            }
        }
        return bounds;
    }

    private static ClassPool.Owned method(ClassPool pool, String owner, String name, String descEnd) {
        ClassNode c = pool.get(owner);
        if (c != null) {
            for (MethodNode m : c.methods) {
                if (m.name.equals(name) && m.desc.endsWith(descEnd)) {
                    return new ClassPool.Owned(c, m);
                }
            }
        }
        return null;
    }

    private static void report(PrintStream out, String what, Job job, List<ClassPool.Owned> entries, AbortBound.Result r,
                               JsonNode summary) {
        out.println("abort-bound: " + what + ", job from " + String.join(", ", entries.stream()
                .map(e -> e.owner().name.replace('/', '.') + "." + e.method().name).toList()) + " (" + r.jobMethods() + " methods)");
        out.println("abort points: " + (job.mode() == AbortBound.Mode.COOPERATIVE
                ? "the job's polls of its abort signal (it returns at the first that sees the request)"
                : "delivery points reached through the job's signal " + String.join(", ", r.signals().stream()
                        .map(s -> s.replace('/', '.')).toList()) + (r.signalDelivers() ? "" : ": none (it calls no Atc.poll)")));
        out.println("particle loops (gap: particle steps between two abort points; bytecodes of one step):");
        for (AbortPollCheck.LoopGap l : r.loops()) {
            out.printf("  %-62s %-16s %6d bytecodes%n", l.where(), l.steps() == AbortPollCheck.UNKNOWN ? "whole loop"
                    : "every " + l.steps(), r.stepBytecodes().get(l));
        }
        AbortPollCheck.LoopGap longest = r.longest();
        if (r.wholeJob()) {
            out.println("longest path between two abort points: the whole job (no abort point between its start and its end)");
        } else if (longest != null) {
            out.println("longest path between two abort points: " + (longest.steps() == AbortPollCheck.UNKNOWN ? "a whole loop"
                    : longest.steps() + " particle steps (at most " + r.longestBytecodes() + " bytecodes)") + ", at " + longest.where());
        }
        out.println("deferral regions:" + (r.deferrals().isEmpty() ? " none" : ""));
        r.deferrals().forEach(d -> out.println("  " + d));
        if (summary != null) {
            withRun(out, r, summary);
        }
    }

    /** The bound in time from the run's task latency per particle, beside the run's measured abort latency. */
    private static void withRun(PrintStream out, AbortBound.Result r, JsonNode s) {
        int particles = s.path("parameters").path("particles").asInt();
        JsonNode abort = s.path("tasks").path("all").path("abortLatencyNs");
        // the costlier task's latency per particle: a step of any loop of either job costs no more
        double p50 = 0;
        double max = 0;
        for (String task : List.of("predict", "update")) {
            JsonNode lat = s.path("tasks").path(task).path("taskLatencyNs");
            p50 = Math.max(p50, lat.path("p50").asDouble(0));
            max = Math.max(max, lat.path("max").asDouble(0));
        }
        if (particles <= 0 || max <= 0) {
            out.println("run: no completed job to take a particle step's cost from");
            return;
        }
        out.printf(Locale.ROOT, "run: %d particles, the costlier task's latency p50 %s max %s: a particle step %.3f us (from the max: %.3f us)%n",
                particles, ms(p50), ms(max), p50 / particles / 1e3, max / particles / 1e3);
        long steps = r.longestSteps();
        if (r.wholeJob() || steps == AbortPollCheck.UNKNOWN) {
            out.printf(Locale.ROOT, "bound on abort latency: the whole job, its remaining time: up to a job's latency (p50 %s, max %s)%n",
                    ms(p50), ms(max));
        } else {
            out.printf(Locale.ROOT, "bound on abort latency: %d steps x step = %s (from the max: %s), plus the code between loops "
                    + "and the unwinding%n", steps, ms(steps * p50 / particles), ms(steps * max / particles));
        }
        if (abort.path("count").asInt() == 0) {
            out.println("measured abort latency: no abort took hold in this run");
        } else {
            out.printf(Locale.ROOT, "measured abort latency: %d jobs (%d completed all the same), p50 %s p99 %s max %s%n",
                    abort.path("count").asInt(), s.path("tasks").path("all").path("abortsCompleted").asInt(),
                    ms(abort.path("p50").asDouble()), ms(abort.path("p99").asDouble()), ms(abort.path("max").asDouble()));
            // what the bound bounds: from the request to the abort point that saw it (seen_ns)
            JsonNode notice = s.path("tasks").path("all").path("abortNoticeNs");
            if (notice.path("count").asInt() > 0) {
                out.printf(Locale.ROOT, "measured noticing (what the bound bounds): %d jobs, p50 %s p99 %s max %s%n",
                        notice.path("count").asInt(), ms(notice.path("p50").asDouble()), ms(notice.path("p99").asDouble()),
                        ms(notice.path("max").asDouble()));
            }
        }
    }

    private static String ms(double ns) {
        return String.format(Locale.ROOT, "%.3f ms", ns / 1e6);
    }

    /** The largest summary.json read (a run's is about 10 KB), as the runner's matrix takes it. */
    static final long MAX_SUMMARY_BYTES = 16L * 1024 * 1024;

    private static int bad(PrintStream err, String message) {
        return CommandLines.bad(err, "abort-bound", message);
    }
}
