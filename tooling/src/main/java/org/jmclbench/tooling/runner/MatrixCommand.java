package org.jmclbench.tooling.runner;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.Callable;

import org.jmclbench.tooling.runtime.RuntimeDiscovery;

import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

/** Runs a matrix of runtimes x profiles x engines x memory styles x policies x particles x datasets x repetitions. */
@Command(name = "matrix", mixinStandardHelpOptions = true, sortOptions = false,
        description = {"Runs a matrix of runtimes x profiles x engines x memory styles x policies x particles x datasets",
                "x repetitions, each run a fresh",
                "process with a timeout, into a SQLite database (raw run folders beside it under runs/). Rerunning the same",
                "command resumes: runs already in the database are skipped. Lists take commas and repeats.",
                "Exit code 0 when the matrix completed (failed runs are recorded and listed), 2 for bad input (nothing runs)."},
        footer = {"", "Example: matrix --runtimes temurin-25,native --java /opt/jdk/bin/java --profiles g1,zgc --policies skip,terminate \\",
                "           --particles 100,400,1600 --datasets match-short --repeat 3 --db results/results.db",
                "Matrix file (--matrix): 'key = value' lines, keys are these long options without dashes, e.g.",
                "  runtimes = temurin-25, native", "  engines = javase, scj", "  particles = 100, 400, 1600",
                "Options on the command line replace the file's values."})
public final class MatrixCommand implements Callable<Integer> {

    @Spec
    CommandSpec commandSpec;

    @Option(names = "--matrix", paramLabel = "FILE", description = "read settings from a matrix file (see below)")
    Path matrixFile;
    @Option(names = "--runtimes", paramLabel = "LIST", description = "runtime names from `jvms`, `native`, `hvm`, `jvms` (all JVMs), `all` (default: all found)")
    List<String> runtimes = new ArrayList<>();
    @Option(names = "--java", paramLabel = "PATH", description = "a JVM by path (java executable or JDK folder), repeatable")
    List<String> javas = new ArrayList<>();
    @Option(names = "--profiles", paramLabel = "LIST", description = "profiles, components joined by '+': default, serial, parallel, g1, zgc, shenandoah, epsilon, int, c1, pretouch, fifo, pinned, aot (default: default)")
    List<String> profiles = new ArrayList<>();
    @Option(names = "--policies", paramLabel = "LIST", description = "skip, terminate, queue, ideal (default: skip)")
    List<String> policies = new ArrayList<>();
    @Option(names = "--engines", paramLabel = "LIST", description = "engines of the JVM runs: javase, scj (default: javase; native runs are engine native)")
    List<String> engines = new ArrayList<>();
    @Option(names = "--memory", paramLabel = "LIST", description = "memory styles: preallocated, allocating (javase, native), scoped (scj); one an engine lacks is recorded unsupported (default: preallocated)")
    List<String> memory = new ArrayList<>();
    @Option(names = "--particles", paramLabel = "LIST", description = "particle counts (default: 400)")
    List<String> particles = new ArrayList<>();
    @Option(names = "--datasets", paramLabel = "LIST", description = "dataset names under data/ or folders (default: match-short)")
    List<String> datasets = new ArrayList<>();
    @Option(names = "--load", paramLabel = "LIST", description = "load scenarios beside each run: none, cpu (stress-ng, else own busy processes), alloc (allocation thread in the JVM under test), mixed (default: none)")
    List<String> loads = new ArrayList<>();
    @Option(names = "--load-alloc", paramLabel = "MBPS,LIVEMB", description = "the alloc load: MB/s allocated and MB kept live (default: 100,16)")
    String loadAlloc;
    @Option(names = "--repeat", paramLabel = "N", description = "repetitions of each configuration (default: 1)")
    String repeat;
    @Option(names = "--shard", paramLabel = "K/N", description = "run only the K-th of N shares of the matrix (merge the databases afterwards)")
    String shard;
    @Option(names = "--order-seed", paramLabel = "N", description = "seed of the shuffled run order (default: random, recorded)")
    String orderSeed;
    @Option(names = "--seed", paramLabel = "N", description = "workload seed of repetition 1; repetition r uses seed+r-1 (default: 1)")
    String seed;
    @Option(names = "--timeout", paramLabel = "S", description = "timeout of one run in seconds (default: replay duration x 3 + 60)")
    String timeout;
    @Option(names = "--time-scale", paramLabel = "F", description = "the workload's --time-scale (default: 1.0)")
    String timeScale;
    @Option(names = "--pin-cpu", paramLabel = "CPUS", description = "CPU list for the pinned profile (default: last isolated CPU, else the last CPU)")
    String pinCpu;
    @Option(names = "--workload-arg", paramLabel = "ARGS", description = "more workload options, split at spaces, e.g. \"--memory allocating\" (repeatable)")
    List<String> workloadArgs = new ArrayList<>();
    @Option(names = "--db", paramLabel = "FILE", description = "results database (default: results/results.db)")
    String db;
    @Option(names = "--native", paramLabel = "PATH", description = "the native baseline binary (default: native/build/jmclbench-native)")
    String nativeBinary;
    @Option(names = "--retry-failed", description = "also rerun runs recorded as failed or timed out (unsupported ones stay)")
    boolean retryFailed;
    @Option(names = "--dry-run", description = "print the planned runs in order and stop")
    boolean dryRun;

    @Override
    public Integer call() throws Exception {
        MatrixSpec spec = toSpec();
        String command = "jmclbench matrix " + String.join(" ", commandSpec.commandLine().getParseResult().originalArgs());
        return MatrixSession.execute(spec, command, System.out, RuntimeDiscovery::discover).exitCode();
    }

    MatrixSpec toSpec() {
        MatrixSpec spec = new MatrixSpec();
        if (matrixFile != null) {
            MatrixFile.read(matrixFile, spec);
        }
        list(spec, "runtimes", runtimes);
        list(spec, "java", javas);
        list(spec, "profiles", profiles);
        list(spec, "policies", policies);
        list(spec, "engines", engines);
        list(spec, "memory", memory);
        list(spec, "particles", particles);
        list(spec, "datasets", datasets);
        list(spec, "load", loads);
        list(spec, "workload-arg", workloadArgs);
        one(spec, "repeat", repeat);
        one(spec, "shard", shard);
        one(spec, "order-seed", orderSeed);
        one(spec, "seed", seed);
        one(spec, "timeout", timeout);
        one(spec, "time-scale", timeScale);
        one(spec, "load-alloc", loadAlloc);
        one(spec, "pin-cpu", pinCpu);
        one(spec, "db", db);
        one(spec, "native", nativeBinary);
        spec.retryFailed = retryFailed;
        spec.dryRun = dryRun;
        return spec;
    }

    static void list(MatrixSpec spec, String key, List<String> values) {
        if (!values.isEmpty()) {
            MatrixOptions.clear(spec, key);
            values.forEach(v -> MatrixOptions.apply(spec, key, v, "--" + key));
        }
    }

    static void one(MatrixSpec spec, String key, String value) {
        if (value != null) {
            MatrixOptions.apply(spec, key, value, "--" + key);
        }
    }
}
