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
            "--time-scale", "--force", "-h", "--help", "--engine", "--memory");

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
        if (policies.contains("ideal")) {
            refuseWhatIdealRunsRefuse(workloadArgs, argWhere);
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
     * The workload refuses what an ideal run cannot apply (a spin before each release, SCJ area
     * sizes: exit 2, IdealEngine), so a matrix with the policy ideal and such a --workload-arg
     * would record its ideal runs failed, one by one: refused here instead, before anything runs.
     */
    private static void refuseWhatIdealRunsRefuse(List<String> args, List<String> where) {
        for (int i = 0; i < args.size(); i++) {
            String[] nameValue = args.get(i).split("=", 2);
            String value = nameValue.length == 2 ? nameValue[1] : i + 1 < args.size() ? args.get(i + 1) : "";
            boolean spin = nameValue[0].equals("--spin-us") && value.matches("\\+?0*[1-9][0-9]*");
            if (spin || nameValue[0].equals("--area-size")) {
                throw new BadUsageException(where.get(i) + ": '" + nameValue[0] + "' with the policy ideal: an ideal run"
                        + (spin ? " has no releases to spin before" : " has no SCJ memory areas")
                        + " (drop ideal from --policies, or give it a matrix of its own)");
            }
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
