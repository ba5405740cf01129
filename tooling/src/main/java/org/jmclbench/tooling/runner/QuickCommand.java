package org.jmclbench.tooling.runner;

import java.util.List;
import java.util.Locale;
import java.util.stream.Collectors;
import java.util.concurrent.Callable;

import org.jmclbench.tooling.cli.BadUsageException;
import org.jmclbench.tooling.report.ReportCommand;
import org.jmclbench.tooling.runtime.RuntimeDiscovery;
import org.jmclbench.tooling.runtime.RuntimeInfo;

import picocli.CommandLine.Command;
import picocli.CommandLine.Option;

/**
 * A first answer in minutes: every JVM found (its default GC) with the Java SE and the SCJ engine,
 * and native, two policies, two sizes.
 */
@Command(name = "quick", mixinStandardHelpOptions = true,
        header = "The main job: every JVM found, C and the HVM, then the report.",
        description = {"Runs every JVM found (with its default GC) with the javase and scj engines, the native "
                + "baseline and, with HVM_SRC set, the icecap HVM (compiled to C), x {skip, terminate} x {100, 1600} particles x 1 repetition "
                + "on dataset " + QuickCommand.DATASET + " (10 s), then the rtsj engine's two designs (rtsj, rtsj-atomic) under "
                + "terminate at 1600 particles on the newest JVM, into results/results.db, then builds the report. It is a matrix: "
                + "rerunning it resumes, and `matrix` can add to the same database. With many runtimes, the replay is sped up "
                + "to stay under 5 minutes (--time-scale, which scales deadlines too); the estimate and the chosen scale are printed."})
public final class QuickCommand implements Callable<Integer> {

    /** The grid: every JVM runs both engines; native runs once per cell. */
    static final List<String> ENGINES = List.of(Engines.JAVASE, Engines.SCJ);
    static final List<String> POLICIES = List.of("skip", "terminate");
    /** Two sizes, light and heavy: with both engines, three sizes would not fit 2 JVMs in 5 minutes. */
    static final List<Integer> PARTICLES = List.of(100, 1600);

    /** The first 10 s of the match route: short enough that two JVMs and native replay in real time. */
    static final String DATASET = "match-quick";

    /** The time quick allows its runs (discovery, probes and the report need the rest of 5 minutes). */
    static final int BUDGET_S = 250;
    /**
     * JVM start, warm-up (the SCJ engine's class-loading mission), folder writing and attribution on
     * top of the replay: measured 2.4-6.5 s, mean 4.2 s, for both engines during a quick on the
     * shared 2-core VM at load average 9 (1.2-3 s for the Java SE engine on a quiet one).
     */
    static final double JVM_OVERHEAD_S = 4.0;
    /** What the estimate leaves out (measured 15-50 s on the 2-core VM, more under heavy load). */
    static final String REPORT_NOTE = ", then the report";

    /** The native baseline starts in milliseconds. */
    static final double NATIVE_OVERHEAD_S = 0.1;

    @Option(names = "--db", paramLabel = "FILE", description = "results database (default: results/results.db)")
    String db = MatrixDefaults.DB;

    @Option(names = "--time-scale", paramLabel = "F", description = "replay speed-up (default: 1.0, or what fits the time budget)")
    String timeScale;

    @Option(names = "--no-report", description = "do not build the report")
    boolean noReport;

    @Override
    public Integer call() throws Exception {
        MatrixSpec spec = spec(db);
        RuntimeDiscovery d = RuntimeDiscovery.discover();
        if (timeScale != null) {
            MatrixOptions.apply(spec, "time-scale", timeScale, "--time-scale");
        } else {
            double scale = fitScale(d, spec);
            if (scale < 1.0) {
                MatrixOptions.apply(spec, "time-scale", String.valueOf(scale), "quick");
            }
        }
        String command = "jmclbench quick" + (timeScale == null ? "" : " --time-scale " + timeScale);
        MatrixSession.Result r = MatrixSession.execute(spec, command, System.out, () -> d);
        if (r.exitCode() != 0) {
            return r.exitCode();
        }
        // the thesis's RTSJ program (both designs) under terminate, where its ATC matters, on the newest JVM
        java.util.Optional<String> newest = newestJvm(d);
        if (newest.isPresent()) {
            MatrixSpec rtsj = rtsjSpec(db, newest.get());
            if (spec.timeScale != null) {
                MatrixOptions.apply(rtsj, "time-scale", String.valueOf(spec.timeScale), "quick");
            }
            r = MatrixSession.execute(rtsj, command + " [rtsj]", System.out, () -> d);
            if (r.exitCode() != 0) {
                return r.exitCode();
            }
        }
        if (noReport) {
            System.out.println("results in " + r.db() + " (report: ./jmclbench report --db " + r.db() + ")");
            return 0;
        }
        try {
            ReportCommand.build(r.db(), null, true);
        } catch (BadUsageException | java.io.IOException e) {
            // the runs are recorded either way: say why the page is missing and how to build it later
            System.err.println("jmclbench: report: " + e.getMessage());
            System.out.println("results in " + r.db() + "; the report could not be built (./jmclbench report --db " + r.db() + ")");
        }
        return 0;
    }

    /** quick's matrix: every runtime, both engines, the grid above, into {@code db}. */
    static MatrixSpec spec(String db) {
        MatrixSpec spec = new MatrixSpec();
        MatrixOptions.apply(spec, "runtimes", "all", "quick");
        MatrixOptions.apply(spec, "engines", String.join(",", ENGINES), "quick");
        MatrixOptions.apply(spec, "policies", String.join(",", POLICIES), "quick");
        MatrixOptions.apply(spec, "particles", PARTICLES.stream().map(String::valueOf).collect(Collectors.joining(",")), "quick");
        MatrixOptions.apply(spec, "datasets", DATASET, "quick");
        MatrixOptions.apply(spec, "repeat", "1", "quick");
        MatrixOptions.apply(spec, "db", db, "--db");
        // the order seed is fixed so that a rerun of quick resumes in the same order
        MatrixOptions.apply(spec, "order-seed", "1", "quick");
        return spec;
    }

    /** The RTSJ engine's designs quick runs, under terminate only (skip does not tell the designs apart). */
    static final List<String> RTSJ_ENGINES = List.of(Engines.RTSJ, Engines.RTSJ_ATOMIC);

    /** quick's RTSJ matrix: both designs on {@code jvm}, terminate, quick's heavier count only (where aborts take time), into {@code db}. */
    static MatrixSpec rtsjSpec(String db, String jvm) {
        MatrixSpec spec = spec(db);
        MatrixOptions.clear(spec, "runtimes");
        MatrixOptions.apply(spec, "runtimes", jvm, "quick");
        MatrixOptions.clear(spec, "engines");
        MatrixOptions.apply(spec, "engines", String.join(",", RTSJ_ENGINES), "quick");
        MatrixOptions.clear(spec, "policies");
        MatrixOptions.apply(spec, "policies", "terminate", "quick");
        MatrixOptions.clear(spec, "particles");
        MatrixOptions.apply(spec, "particles", String.valueOf(PARTICLES.get(PARTICLES.size() - 1)), "quick");
        return spec;
    }

    /** The JVM of the highest major version found (the first found on a tie). */
    static java.util.Optional<String> newestJvm(RuntimeDiscovery d) {
        return d.jvms().stream().max(java.util.Comparator.comparingInt(RuntimeInfo::major)).map(RuntimeInfo::name);
    }

    /**
     * The largest scale in steps of 0.05 (at least 0.25) that keeps the runs within {@link #BUDGET_S};
     * prints the estimate either way.
     */
    static double fitScale(RuntimeDiscovery d, MatrixSpec spec) {
        boolean nat = d.nativeBaseline().isPresent()
                || java.nio.file.Files.isExecutable(org.jmclbench.tooling.runtime.JmclbenchPaths.nativeBinary());
        double duration;
        try {
            duration = Dataset.resolve(DATASET, org.jmclbench.tooling.runtime.JmclbenchPaths.home(), "quick").durationS();
        } catch (BadUsageException e) {
            return 1.0; // the session reports the missing dataset
        }
        // the HVM joins "all" when HVM_SRC is set; its runs start a JVM and the executable
        boolean hvm = org.jmclbench.tooling.runtime.HvmRuntime.sourceGiven();
        return fitScale(d.jvms().size(), nat, hvm, duration, System.out);
    }

    /**
     * {@link #fitScale(RuntimeDiscovery, MatrixSpec)} for {@code jvms} JVMs, native or not, the HVM or not,
     * a dataset of {@code durationS}. Native and the HVM run once per cell (their engine is their own).
     */
    static double fitScale(int jvms, boolean nat, boolean hvm, double durationS, java.io.PrintStream out) {
        int cells = POLICIES.size() * PARTICLES.size();
        int jvmRuns = jvms * ENGINES.size() * cells + (hvm ? cells : 0) + (jvms > 0 ? RTSJ_ENGINES.size() : 0);
        int nativeRuns = nat ? cells : 0;
        int runs = jvmRuns + nativeRuns;
        if (runs == 0 || durationS <= 0) {
            return 1.0;
        }
        double overhead = jvmRuns * JVM_OVERHEAD_S + nativeRuns * NATIVE_OVERHEAD_S;
        double scale = Math.floor((BUDGET_S - overhead) / (runs * durationS) * 20) / 20;
        if (scale >= 1.0) {
            out.printf(Locale.ROOT, "quick: %d runs (%d JVM x %d engines x %d settings%s) of %.0f s: about %.0f s in real time"
                            + REPORT_NOTE + "%n",
                    runs, jvms, ENGINES.size(), cells, (nat ? " + native" : "") + (hvm ? " + hvm" : "") + (jvms > 0 ? " + rtsj" : ""),
                    durationS, runs * durationS + overhead);
            return 1.0;
        }
        double chosen = Math.max(0.25, scale);
        out.printf(Locale.ROOT, "quick: %d runs of %.0f s would take about %.0f s; replaying at --time-scale %.2f"
                        + " (about %.0f s; deadlines scale too)" + REPORT_NOTE + "%n", runs, durationS, runs * durationS + overhead, chosen,
                runs * durationS * chosen + overhead);
        return chosen;
    }
}
