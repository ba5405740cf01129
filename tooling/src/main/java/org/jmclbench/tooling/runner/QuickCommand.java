package org.jmclbench.tooling.runner;

import java.util.Locale;
import java.util.concurrent.Callable;

import org.jmclbench.tooling.cli.JmclbenchCli;
import org.jmclbench.tooling.runtime.BadUsageException;
import org.jmclbench.tooling.runtime.RuntimeDiscovery;

import picocli.CommandLine.Command;
import picocli.CommandLine.Option;

/** A first answer in minutes: every JVM found (its default GC) and native, two policies, three sizes. */
@Command(name = "quick", mixinStandardHelpOptions = true,
        description = {"Runs every JVM found (with its default GC), the native baseline and, with HVM_SRC set, the icecap HVM x {skip, terminate} x",
                "{100, 400, 1600} particles x 1 repetition on dataset " + QuickCommand.DATASET + " (10 s) into results/results.db, then",
                "builds the report. It is a matrix: rerunning it resumes, and `matrix` can add to the same database.",
                "With many runtimes, the replay is sped up to stay under " + QuickCommand.BUDGET_S / 60 + " minutes",
                "(--time-scale, which scales deadlines too); the chosen scale is printed."})
public final class QuickCommand implements Callable<Integer> {

    /** The first 10 s of the match route: short enough that two JVMs and native replay in real time. */
    static final String DATASET = "match-quick";

    /** The time quick allows its runs (the report and set-up need the rest of 5 minutes). */
    static final int BUDGET_S = 240;
    /** JVM start, warm-up and folder writing on top of the replay (measured 1.2-3 s on the 2-core VM). */
    static final double JVM_OVERHEAD_S = 2.5;
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
        MatrixSession.Result r;
        try {
            MatrixSpec spec = new MatrixSpec();
            MatrixOptions.apply(spec, "runtimes", "all", "quick");
            MatrixOptions.apply(spec, "policies", "skip,terminate", "quick");
            MatrixOptions.apply(spec, "particles", "100,400,1600", "quick");
            MatrixOptions.apply(spec, "datasets", DATASET, "quick");
            MatrixOptions.apply(spec, "repeat", "1", "quick");
            MatrixOptions.apply(spec, "db", db, "--db");
            // the order seed is fixed so that a rerun of quick resumes in the same order
            MatrixOptions.apply(spec, "order-seed", "1", "quick");
            RuntimeDiscovery d = RuntimeDiscovery.discover();
            if (timeScale != null) {
                MatrixOptions.apply(spec, "time-scale", timeScale, "--time-scale");
            } else {
                double scale = fitScale(d, spec);
                if (scale < 1.0) {
                    MatrixOptions.apply(spec, "time-scale", String.valueOf(scale), "quick");
                }
            }
            r = MatrixSession.execute(spec, "jmclbench quick" + (timeScale == null ? "" : " --time-scale " + timeScale),
                    System.out, () -> d);
        } catch (BadUsageException e) {
            throw e.checked();
        }
        if (r.exitCode() != 0) {
            return r.exitCode();
        }
        if (noReport) {
            System.out.println("results in " + r.db() + " (report: ./jmclbench report --db " + r.db() + ")");
            return 0;
        }
        int rc = JmclbenchCli.execute("report", "--db", r.db().toString());
        if (rc != 0) {
            System.out.println("results in " + r.db() + "; the report could not be built (./jmclbench report --db " + r.db() + ")");
        }
        return 0;
    }

    /** The largest scale in steps of 0.05 (at least 0.25) that keeps the runs within {@link #BUDGET_S}. */
    static double fitScale(RuntimeDiscovery d, MatrixSpec spec) {
        boolean nat = d.nativeBaseline().isPresent()
                || java.nio.file.Files.isExecutable(org.jmclbench.tooling.runtime.JmclbenchPaths.nativeBinary());
        int jvmRuns = d.jvms().size() * 2 * 3;
        int nativeRuns = nat ? 2 * 3 : 0;
        // the HVM joins "all" when HVM_SRC is set; its runs start a JVM and the executable
        int hvmRuns = org.jmclbench.tooling.runtime.HvmRuntime.sourceGiven() ? 2 * 3 : 0;
        double duration;
        try {
            duration = Dataset.resolve(DATASET, org.jmclbench.tooling.runtime.JmclbenchPaths.home(), "quick").durationS();
        } catch (BadUsageException e) {
            return 1.0; // the session reports the missing dataset
        }
        int runs = jvmRuns + nativeRuns + hvmRuns;
        if (runs == 0 || duration <= 0) {
            return 1.0;
        }
        double overhead = (jvmRuns + hvmRuns) * JVM_OVERHEAD_S + nativeRuns * NATIVE_OVERHEAD_S;
        double scale = Math.floor((BUDGET_S - overhead) / (runs * duration) * 20) / 20;
        if (scale >= 1.0) {
            return 1.0;
        }
        double chosen = Math.max(0.25, scale);
        System.out.printf(Locale.ROOT, "quick: %d runs of %.0f s would take about %.0f s; replaying at --time-scale %.2f"
                        + " (about %.0f s; deadlines scale too)%n", runs, duration, runs * duration + overhead, chosen,
                runs * duration * chosen + overhead);
        return chosen;
    }
}
