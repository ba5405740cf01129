package org.jmclbench.tooling.runner;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Random;
import java.util.Set;
import java.util.function.Supplier;
import java.util.stream.Collectors;

import org.jmclbench.tooling.cli.BadUsageException;
import org.jmclbench.tooling.load.LoadScenario;
import org.jmclbench.tooling.runtime.HvmRuntime;
import org.jmclbench.tooling.runtime.LaunchPlan;
import org.jmclbench.tooling.runtime.Profile;
import org.jmclbench.tooling.runtime.RuntimeDiscovery;
import org.jmclbench.tooling.runtime.RuntimeInfo;
import org.jmclbench.tooling.runtime.RuntimeKind;
import org.jmclbench.tooling.store.MachineInfo;

/**
 * Resolves a {@link MatrixSpec} against this machine and plans its runs: every combination of
 * runtime x profile x engine x memory style x policy x particles x dataset x load x repetition, each with a run key (a hash of
 * machine, configuration and repetition, so that a rerun finds what is done), this shard's share,
 * in an order shuffled within each repetition round from a recorded seed, so that machine drift
 * does not favour one configuration and round 1 of every configuration ends before round 2 starts.
 * A native runtime keeps only the OS part of each profile (fifo, pinned) and has one engine, {@code native};
 * its duplicates are dropped. A memory style the engine lacks is planned, and recorded unsupported.
 */
public final class MatrixPlanner {

    /** Options the runner sets itself, which {@code --workload-arg} may not repeat. */
    static final Set<String> RESERVED_ARGS = Set.of("-p", "--particles", "-n", "--number", "-j", "--runtime-name",
            "-O", "--out", "--dataset", "-odo", "-laser", "-real", "-T", "--policy", "--ideal", "--seed",
            "--time-scale", "--force", "-h", "--help", "--engine", "--memory",
            // the load scenario (--load, --load-alloc) and the fifo profile (the C baseline's --no-fifo)
            "--load-alloc", "--load-name", "--no-fifo");

    /** The Java workload's options that the C baseline lacks, and refuses as unknown (docs/FORMATS.md section 2). */
    static final Set<String> JAVA_ONLY_ARGS = Set.of("--engine", "--rtsj-design", "--area-size", "--load-alloc",
            "--load-name");

    private MatrixPlanner() {
    }

    /**
     * @param discovery finds the installed runtimes (called only when a name needs it)
     * @throws BadUsageException on anything wrong with the spec, naming where it came from
     */
    public static ResolvedMatrix resolve(MatrixSpec spec, Supplier<RuntimeDiscovery> discovery, Path home,
                                         MachineInfo machine) {
        Path nativeBinary = spec.nativeBinary != null ? spec.nativeBinary.toAbsolutePath()
                : home.resolve("native/build/jmclbench-native");
        List<RuntimeInfo> runtimes = resolveRuntimes(spec, discovery, nativeBinary, home);
        List<Profile> profiles = new ArrayList<>();
        if (spec.profiles.isEmpty()) {
            MatrixDefaults.PROFILES.forEach(p -> profiles.add(Profile.parse(p, "--profiles")));
        }
        for (Sourced<String> p : spec.profiles) {
            Profile parsed = Profile.parse(p.value(), p.where());
            if (profiles.stream().noneMatch(q -> q.name().equals(parsed.name()))) {
                profiles.add(parsed);
            }
        }
        List<String> policies = distinct(spec.policies.isEmpty() ? MatrixDefaults.POLICIES
                : spec.policies.stream().map(Sourced::value).toList());
        List<String> engines = distinct(spec.engines.isEmpty() ? MatrixDefaults.ENGINES
                : spec.engines.stream().map(Sourced::value).toList());
        List<String> memory = distinct(spec.memory.isEmpty() ? MatrixDefaults.MEMORY
                : spec.memory.stream().map(Sourced::value).toList());
        List<Integer> particles = distinct(spec.particles.isEmpty() ? MatrixDefaults.PARTICLES
                : spec.particles.stream().map(Sourced::value).toList());
        List<Dataset> datasets = new ArrayList<>();
        List<Sourced<String>> ds = spec.datasets.isEmpty()
                ? MatrixDefaults.DATASETS.stream().map(d -> new Sourced<>(d, "--datasets")).toList() : spec.datasets;
        for (Sourced<String> d : ds) {
            Dataset resolved = Dataset.resolve(d.value(), home, d.where());
            if (datasets.stream().noneMatch(x -> x.dir().equals(resolved.dir()))) {
                datasets.add(resolved);
            }
        }
        List<LoadScenario> loads = new ArrayList<>();
        for (Sourced<String> l : spec.loads) {
            LoadScenario s = LoadScenario.parse(l.where(), l.value());
            if (!loads.contains(s)) {
                loads.add(s);
            }
        }
        if (loads.isEmpty()) {
            loads.add(LoadScenario.NONE);
        }
        org.jmclbench.tooling.load.LoadSettings loadSettings = spec.loadSettings != null ? spec.loadSettings
                : org.jmclbench.tooling.load.LoadSettings.defaults();
        List<String> workloadArgs = new ArrayList<>();
        List<String> argWhere = new ArrayList<>();
        for (Sourced<String> a : spec.workloadArgs) {
            if (a.value().isBlank()) {
                // it would pass an empty argument, which the workload refuses, under the run key of no argument
                throw new BadUsageException(a.where() + ": empty value");
            }
            for (String w : a.value().strip().split("\\s+")) {
                if (RESERVED_ARGS.contains(w) || RESERVED_ARGS.contains(w.split("=", 2)[0])) {
                    throw new BadUsageException(a.where() + ": '" + w + "' is set by the runner (use the matrix option)");
                }
                workloadArgs.add(w);
                argWhere.add(a.where());
            }
        }
        int repeat = spec.repeat != null ? spec.repeat : MatrixDefaults.REPEAT;
        long seed = spec.seed != null ? spec.seed : MatrixDefaults.SEED;
        long orderSeed = spec.orderSeed != null ? spec.orderSeed : new Random().nextLong();
        double timeScale = spec.timeScale != null ? spec.timeScale : MatrixDefaults.TIME_SCALE;
        String pinCpu = spec.pinCpu != null ? spec.pinCpu : LaunchPlan.defaultPinCpu();
        Path db = (spec.db != null ? spec.db : Path.of(MatrixDefaults.DB)).toAbsolutePath().normalize();

        Map<String, PlannedRun> all = new LinkedHashMap<>();
        for (RuntimeInfo rt : runtimes) {
            // a native program has one engine: one native run per cell, whatever --engines says
            List<String> rtEngines = distinct(engines.stream().map(e -> Engines.of(rt, e)).toList());
            for (Profile prof : profiles) {
                Profile effective = prof.effectiveFor(rt.kind());
                for (String engine : rtEngines) {
                    for (String mem : memory) {
                        for (String policy : policies) {
                            for (int n : particles) {
                                for (Dataset d : datasets) {
                                    for (LoadScenario load : loads) {
                                        for (int rep = 1; rep <= repeat; rep++) {
                                            long runSeed = seed + rep - 1;
                                            String key = runKey(machine, rt, effective, engine, mem, policy, n, d, load,
                                                    loadSettings, rep, runSeed, timeScale, workloadArgs);
                                            all.putIfAbsent(key, new PlannedRun(rt, effective, engine, mem, policy, n, d, rep,
                                                    runSeed, load, key));
                                        }
                                    }
                                }
                            }
                        }
                    }
                }
            }
        }
        checkWorkloadOptions(all.values(), timeScale, workloadArgs, argWhere);
        List<PlannedRun> mine = new ArrayList<>(all.values());
        if (spec.shard != null) {
            List<PlannedRun> byKey = new ArrayList<>(all.values());
            byKey.sort(Comparator.comparing(PlannedRun::runKey));
            mine = new ArrayList<>();
            for (int i = 0; i < byKey.size(); i++) {
                if (i % spec.shard[1] == spec.shard[0] - 1) {
                    mine.add(byKey.get(i));
                }
            }
        }
        List<PlannedRun> ordered = order(mine, repeat, orderSeed);
        return new ResolvedMatrix(runtimes, profiles, engines, memory, policies, particles, datasets, List.copyOf(loads), loadSettings, repeat, seed, orderSeed, timeScale,
                spec.timeoutS, pinCpu, List.copyOf(workloadArgs), db, nativeBinary, spec.shard, ordered, all.size());
    }

    /**
     * Checks each cell's workload command line as its engine will (the workload's own RunOptionsParser,
     * docs/FORMATS.md section 2), so that an option an engine refuses (a --workload-arg the scj engine
     * or an ideal run cannot apply, a bad value, an unknown option) is one line and exit 2 here, before
     * anything runs, rather than each of the matrix's runs of that engine recorded failed. The C baseline's
     * parser is the Java one on the options they share (OptionsDifferentialTest holds the two alike);
     * the hvm engine (the HVM launcher's, not on this class path) is checked as the scj engine it extends,
     * then with the hvm engine's own refusals, which the launch contract holds ({@code HvmOptionRules}).
     * A run whose engine lacks its memory style is recorded unsupported and not checked.
     */
    private static void checkWorkloadOptions(java.util.Collection<PlannedRun> runs, double timeScale,
                                             List<String> workloadArgs, List<String> argWhere) {
        Set<String> cells = new java.util.HashSet<>();
        Map<Path, String> warmupRefusals = new java.util.HashMap<>();
        for (PlannedRun run : runs) {
            if (Engines.unsupported(run.engine(), run.memory()) != null
                    || !cells.add(run.runtime().kind() + " " + run.engine() + " " + run.memory() + " " + run.policy()
                            + " " + run.profile().has(org.jmclbench.tooling.runtime.ProfileComponent.FIFO)
                            + " " + run.dataset().dir())) {
                continue;
            }
            String refusal = refusal(run, WorkloadCommand.workloadOptions(run, Path.of("results"), timeScale,
                    workloadArgs), warmupRefusals);
            if (refusal != null) {
                String option = refusal.substring(0, Math.max(0, refusal.indexOf(':')));
                int at = -1;
                for (int i = 0; i < workloadArgs.size() && at < 0; i++) {
                    at = workloadArgs.get(i).split("=", 2)[0].equals(option) ? i : -1;
                }
                String cell = "the " + run.engine() + (run.policy().equals("ideal") ? " ideal" : " " + run.policy())
                        + " runs";
                throw new BadUsageException((at >= 0 ? argWhere.get(at) + ": " : argWhere.isEmpty() ? ""
                        : argWhere.get(0) + ": ") + refusal + " (" + cell + ")");
            }
        }
    }

    /**
     * What the workload of {@code run} says of its command line {@code line}, or null when it takes it;
     * a --warmup is checked against the dataset as the workload checks it ({@code Dataset.checkWarmup}),
     * once per dataset folder ({@code warmupRefusals}, "" when it takes it).
     */
    private static String refusal(PlannedRun run, List<String> line, Map<Path, String> warmupRefusals) {
        List<String> args = new ArrayList<>(line);
        if (run.runtime().kind() == RuntimeKind.NATIVE) {
            for (String a : args) {
                String name = a.split("=", 2)[0];
                if (JAVA_ONLY_ARGS.contains(name) || name.equals("--version")) {
                    return name + (name.equals("--version") ? ": prints the build and runs nothing"
                            : ": unknown option (see --help)");
                }
            }
            args.remove("--no-fifo"); // the C baseline's own, set by the runner
        } else if (run.runtime().kind() == RuntimeKind.HVM) {
            args.set(args.indexOf("hvm"), Engines.SCJ);
        }
        try {
            org.jmclbench.workload.RunOptions options = org.jmclbench.workload.RunOptionsParser.parse(
                    args.toArray(new String[0]));
            if (run.runtime().kind() == RuntimeKind.HVM) {
                // what the hvm engine refuses beyond the scj engine's checks (its --warmup among them)
                org.jmclbench.workload.scj.HvmOptionRules.check(options);
            }
            if (options.warmupS <= 0) {
                return null;
            }
            String warmup = warmupRefusals.computeIfAbsent(run.dataset().dir(),
                    dir -> java.util.Objects.toString(warmupRefusal(dir, options.warmupS), ""));
            return warmup.isEmpty() ? null : warmup;
        } catch (org.jmclbench.workload.BadInputException e) {
            return e.getMessage();
        }
    }

    /**
     * The workload's refusal of a warm-up that leaves no event of the dataset in {@code dir} after it,
     * or null; a dataset the workload cannot read was refused by {@link Dataset#resolve}, naming the file and line.
     */
    private static String warmupRefusal(Path dir, double warmupS) {
        try {
            org.jmclbench.workload.data.DatasetReader.readFolder(dir.toFile()).checkWarmup(warmupS);
            return null;
        } catch (org.jmclbench.workload.BadInputException e) {
            return e.getMessage().startsWith("--warmup: ") ? e.getMessage() : null;
        }
    }

    /**
     * Builds (or finds cached) every HVM executable the profiles of {@code m} ask for, before the first
     * run, so that no run pays for it; nothing when {@code m} has no hvm runtime. Not part of
     * {@link #resolve}: a dry run plans and prints, and builds nothing.
     *
     * @throws BadUsageException when the build refuses its input, and {@link IOException} when an
     *     executable cannot be built, each naming where hvm was asked for ({@code --runtimes: hvm: ...},
     *     or the matrix file's line)
     */
    static void prepareHvm(MatrixSpec spec, ResolvedMatrix m, Path home) throws IOException {
        if (m.runtimes().stream().noneMatch(r -> r.kind() == RuntimeKind.HVM)) {
            return;
        }
        String where = spec.runtimes.stream().filter(r -> r.value().equals(HvmRuntime.NAME)).findFirst()
                .or(() -> spec.runtimes.stream().filter(r -> r.value().equals("all")).findFirst())
                .map(Sourced::where).orElse("--runtimes");
        HvmRuntime.prepare(home, distinct(m.profiles().stream().map(p -> p.effectiveFor(RuntimeKind.HVM).hvmMode()).toList()),
                where);
    }

    /** Shuffles each repetition round with {@code orderSeed}; rounds run in order. */
    static List<PlannedRun> order(List<PlannedRun> runs, int repeat, long orderSeed) {
        Random rnd = new Random(orderSeed);
        List<PlannedRun> out = new ArrayList<>();
        for (int rep = 1; rep <= repeat; rep++) {
            final int r = rep;
            List<PlannedRun> round = new ArrayList<>(runs.stream().filter(p -> p.repetition() == r)
                    .sorted(Comparator.comparing(PlannedRun::runKey)).toList());
            java.util.Collections.shuffle(round, rnd);
            out.addAll(round);
        }
        return out;
    }

    /**
     * The run key. The engine and memory style enter it only when they are not the defaults
     * (javase or native, preallocated), so that the runs of a store made before these dimensions
     * keep their keys and a rerun resumes them.
     */
    static String runKey(MachineInfo m, RuntimeInfo rt, Profile p, String engine, String memory, String policy, int particles,
                         Dataset d, LoadScenario load, org.jmclbench.tooling.load.LoadSettings loadSettings, int rep, long seed,
                         double timeScale, List<String> workloadArgs) {
        boolean defaultEngine = engine.equals(Engines.JAVASE) || engine.equals(Engines.NATIVE);
        String text = String.join("\n", "jmclbench-run-key/1", "machine=" + m.machineId(), "runtime=" + rt.name(),
                "runtimeVersion=" + rt.version(), "profile=" + p.name())
                + (defaultEngine ? "" : "\nengine=" + engine)
                + (memory.equals(Engines.PREALLOCATED) ? "" : "\nmemory=" + memory)
                + "\n" + String.join("\n", "policy=" + policy, "particles=" + particles,
                "dataset=" + d.label() + "@" + d.digest(), "load=" + load.label() + (load.alloc() ? " alloc=" + loadSettings.allocMbPerS() + "," + loadSettings.allocLiveMb() : ""), "repetition=" + rep, "seed=" + seed,
                "timeScale=" + timeScale, "workloadArgs=" + String.join(" ", workloadArgs));
        return MachineInfo.sha256Hex(text).substring(0, 20);
    }

    private static List<RuntimeInfo> resolveRuntimes(MatrixSpec spec, Supplier<RuntimeDiscovery> discovery, Path nativeBinary,
                                                     Path home) {
        boolean needDiscovery = spec.runtimes.isEmpty() && spec.javas.isEmpty()
                || spec.runtimes.stream().anyMatch(r -> !r.value().equals("native") && !r.value().equals(HvmRuntime.NAME));
        RuntimeDiscovery d = needDiscovery ? discovery.get() : RuntimeDiscovery.discover(List.of(), null);
        Map<String, RuntimeInfo> out = new LinkedHashMap<>();
        for (Sourced<String> j : spec.javas) {
            RuntimeInfo r;
            try {
                r = d.addJava(j.value());
            } catch (BadUsageException e) {
                throw new BadUsageException(e.getMessage().replaceFirst("^--java", j.where()));
            }
            out.putIfAbsent(r.name(), r);
        }
        RuntimeInfo nat = Files.isExecutable(nativeBinary) && !Files.isDirectory(nativeBinary)
                ? RuntimeDiscovery.nativeRuntime(nativeBinary) : null;
        if (spec.runtimes.isEmpty() && spec.javas.isEmpty()) {
            d.jvms().forEach(r -> out.putIfAbsent(r.name(), r));
            if (nat != null) {
                out.putIfAbsent("native", nat);
            }
            if (out.isEmpty()) {
                throw new BadUsageException("--runtimes: no runtime found on this machine (./jmclbench jvms; --java PATH)");
            }
        }
        for (Sourced<String> r : spec.runtimes) {
            String name = r.value();
            if (name.equals(HvmRuntime.NAME)) {
                // a dry run asks too: build-hvm.sh --check builds and writes nothing, and what it refuses
                // (a bad HVM_SRC, a missing compiler) the run would refuse, so the plan is refused for it
                HvmRuntime.Availability a = HvmRuntime.check(home);
                if (!a.buildable()) {
                    throw new BadUsageException(r.where() + ": hvm: the icecap HVM cannot be built here: " + a.detail());
                }
                out.putIfAbsent(HvmRuntime.NAME, HvmRuntime.runtime());
            } else if (name.equals("native")) {
                if (nat == null) {
                    throw new BadUsageException(r.where() + ": native: the native baseline is not built (" + nativeBinary + ")");
                }
                out.putIfAbsent("native", nat);
            } else if (name.equals("jvms") || name.equals("all")) {
                d.jvms().forEach(x -> out.putIfAbsent(x.name(), x));
                if (name.equals("all") && nat != null) {
                    out.putIfAbsent("native", nat);
                }
                // all: the HVM too when the user pointed at its source and it can be built
                if (name.equals("all") && HvmRuntime.sourceGiven() && HvmRuntime.check(home).buildable()) {
                    out.putIfAbsent(HvmRuntime.NAME, HvmRuntime.runtime());
                }
            } else {
                RuntimeInfo found = d.find(name).orElseThrow(() -> new BadUsageException(r.where() + ": unknown runtime '"
                        + name + "' (found: " + known(d, nat) + "; or --java PATH)"));
                out.putIfAbsent(found.name(), found);
            }
        }
        return List.copyOf(out.values());
    }

    private static String known(RuntimeDiscovery d, RuntimeInfo nat) {
        Set<String> names = new LinkedHashSet<>(d.jvms().stream().map(RuntimeInfo::name).toList());
        if (nat != null) {
            names.add("native");
        }
        return names.isEmpty() ? "none" : names.stream().collect(Collectors.joining(", "));
    }

    private static <T> List<T> distinct(List<T> l) {
        return List.copyOf(new LinkedHashSet<>(l));
    }
}
