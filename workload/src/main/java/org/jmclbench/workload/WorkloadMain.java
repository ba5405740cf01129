package org.jmclbench.workload;

import java.io.File;
import java.io.IOException;
import java.io.PrintStream;

import org.jmclbench.workload.data.Dataset;
import org.jmclbench.workload.data.DatasetReader;
import org.jmclbench.workload.engine.Engine;
import org.jmclbench.workload.engine.EngineInput;
import org.jmclbench.workload.engine.EngineResult;
import org.jmclbench.workload.engine.Engines;
import org.jmclbench.workload.output.Environment;
import org.jmclbench.workload.output.RunFolder;
import org.jmclbench.workload.output.RunWriter;



/**
 * Entry point of the workload process: {@code [run] [options]} reads a dataset, runs one test
 * (ideal or real-time), writes its run folder and exits 0 (success), 2 (bad usage or input),
 * 3 (a configuration the runtime under test cannot run) or 1 (a failure of the benchmark
 * itself). A folder left behind by a failure is {@code .partial}.
 */
public final class WorkloadMain {
    /** Exit codes of docs/FORMATS.md section 2. */
    public static final int OK = 0;
    public static final int FAILURE = 1;
    public static final int BAD_INPUT = 2;
    public static final int UNSUPPORTED = 3;

    private WorkloadMain() {
    }

    public static void main(String[] args) {
        int code = run(args, System.out, System.err);
        System.out.flush();
        System.exit(code);
    }

    /**
     * Runs the command line, {@code [run] [options]} as the C baseline takes it (the thesis's
     * {@code -p 400 -n 1 ...} has no {@code run}); returns the exit code (for tests: no System.exit).
     */
    public static int run(String[] args, PrintStream out, PrintStream err) {
        try {
            RunOptions options = RunOptionsParser.parse(args);
            if (options.help) {
                out.println(RunOptionsParser.USAGE);
                return OK;
            }
            return execute(options, out, err);
        } catch (BadInputException e) {
            err.println("jmclbench: " + e.getMessage());
            return BAD_INPUT;
        } catch (UnsupportedRunException e) {
            err.println("jmclbench: unsupported: " + e.getMessage());
            return UNSUPPORTED;
        } catch (RunFailure e) {
            err.println("jmclbench: failure: " + e.getMessage());
            return FAILURE;
        } catch (IOException e) {
            err.println("jmclbench: I/O failure: " + e);
            return FAILURE;
        } catch (OutOfMemoryError e) {
            // too little heap for the options, not a bug to trace: say what to change, in one line
            err.println("jmclbench: failure: out of memory (" + e.getMessage() + "): this JVM's heap is at most "
                    + Runtime.getRuntime().maxMemory() / (1024 * 1024) + " MiB (set it with -Xmx; fewer particles need less)");
            return FAILURE;
        } catch (RuntimeException | StackOverflowError e) {
            err.println("jmclbench: failure: " + e);
            e.printStackTrace(err);
            return FAILURE;
        }
    }

    /**
     * The one run lifecycle: the engine checks the dataset before anything is written or
     * started, then the run folder is begun, the environment captured, the engine run, its
     * result written and the folder committed.
     */
    private static int execute(RunOptions options, PrintStream out, PrintStream err)
            throws BadInputException, UnsupportedRunException, IOException, RunFailure {
        Dataset dataset = load(options);
        dataset.checkTimeScale(options.timeScale);
        dataset.checkWarmup(options.warmupS);
        Engine engine = Engines.of(options);
        engine.validate(options, dataset);
        RunFolder folder = RunFolder.of(options);
        folder.checkNotComplete();
        Environment environment = Environment.capture();
        File partial;
        try {
            partial = folder.begin();
        } catch (IOException e) {
            // Almost always a place that cannot be written: bad usage, not a benchmark failure.
            throw BadInputException.ofOption("-O", "cannot create " + folder.partial.getPath() + ": " + e);
        }
        EngineResult result = engine.run(new EngineInput(options, dataset, partial, err));
        new RunWriter(options, dataset, result.records.timeline, result.records, environment).engine(result.facts)
                .memory(result.areas).writeAll(partial);
        folder.commit();
        // The complete run folder, the one line a script needs.
        out.println(folder.dir.getPath());
        return OK;
    }

    /** The dataset the options name: -odo/-laser/-real, --dataset, else data/match-short under the home. */
    static Dataset load(RunOptions o) throws BadInputException {
        if (o.odo != null) {
            return DatasetReader.readFiles(new File(o.odo), new File(o.laser), new File(o.real));
        }
        if (o.dataset != null) {
            return DatasetReader.readFolder(new File(o.dataset));
        }
        String home = System.getProperty("jmclbench.home");
        File base = home != null ? new File(home) : new File(".");
        return DatasetReader.readFolder(new File(base, "data" + File.separator + "match-short"));
    }
}
