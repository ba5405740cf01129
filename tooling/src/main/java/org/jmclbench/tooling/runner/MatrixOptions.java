package org.jmclbench.tooling.runner;

import java.nio.file.Path;
import java.util.List;

import org.jmclbench.tooling.cli.BadUsageException;
import org.jmclbench.tooling.load.LoadScenario;
import org.jmclbench.tooling.load.LoadSettings;
import org.jmclbench.tooling.runtime.CpuList;

/** Parses one matrix setting, from the command line or a matrix file, into a {@link MatrixSpec}. */
final class MatrixOptions {

    /**
     * One matrix setting: its key (a matrix file's key, and with two dashes its option on the command
     * line), whether it is a list, the label of its value and its help text.
     */
    record Setting(String key, boolean list, String label, String description) {
    }

    /** Every matrix setting, in the order of the help. */
    static final List<Setting> SETTINGS = List.of(
            new Setting("runtimes", true, "LIST", "runtime names from `jvms`, `native`, `hvm`, `jvms` (all JVMs), `all` (default: all found)"),
            new Setting("java", true, "PATH", "a JVM by path (java executable or JDK folder), repeatable"),
            new Setting("profiles", true, "LIST", "profiles, components joined by '+': default, serial, parallel, g1, zgc, shenandoah, epsilon, int, c1, pretouch, heap<N>m or heap<N>g (-Xmx), fifo, pinned, noidle, aot (default: default)"),
            new Setting("policies", true, "LIST", String.join(", ", MatrixDefaults.KNOWN_POLICIES) + " (default: skip)"),
            new Setting("engines", true, "LIST", "engines of the JVM runs: " + String.join(", ", Engines.JVM_ENGINES)
                    + " (default: javase; native runs are engine native)"),
            new Setting("memory", true, "LIST", "memory styles: preallocated, allocating (javase, rtsj, rtsj-atomic, native), scoped (scj, hvm); one an engine lacks is recorded unsupported (default: preallocated)"),
            new Setting("particles", true, "LIST", "particle counts (default: 400)"),
            new Setting("datasets", true, "LIST", "dataset names under data/ or folders (default: match-short)"),
            new Setting("load", true, "LIST", "load scenarios beside each run: none, cpu (stress-ng, else own busy processes), alloc (allocation thread in the JVM under test), mixed (default: none)"),
            new Setting("load-alloc", false, "MBPS,LIVEMB", "the alloc load: MB/s allocated and MB kept live (default: 100,16)"),
            new Setting("repeat", false, "N", "repetitions of each configuration, at most 10000 (default: 1)"),
            new Setting("shard", false, "K/N", "run only the K-th of N shares of the matrix (merge the databases afterwards)"),
            new Setting("order-seed", false, "N", "seed of the shuffled run order (default: random, recorded)"),
            new Setting("seed", false, "N", "workload seed of repetition 1; repetition r uses seed+r-1 (default: 1)"),
            new Setting("timeout", false, "S", "timeout of one run in seconds (default: replay duration x 3 + 60)"),
            new Setting("time-scale", false, "F", "the workload's --time-scale (default: 1.0)"),
            new Setting("pin-cpu", false, "CPUS", "CPU list for the pinned profile (default: last isolated CPU, else the last CPU)"),
            new Setting("workload-arg", true, "ARGS", "more workload options, split at spaces, e.g. \"--resample multinomial\" (repeatable; not the options the runner sets itself)"),
            new Setting("db", false, "FILE", "results database (default: results/results.db)"),
            new Setting("native", false, "PATH", "the native baseline binary (default: native/build/jmclbench-native)"));

    /** The most repetitions a matrix takes. */
    static final int MAX_REPEAT = 10_000;

    /** The keys a matrix file accepts (the long options without dashes). */
    static final List<String> KEYS = SETTINGS.stream().map(Setting::key).toList();

    private MatrixOptions() {
    }

    /** Clears a list setting (a command-line list replaces the matrix file's). */
    static void clear(MatrixSpec spec, String key) {
        switch (key) {
            case "runtimes" -> spec.runtimes.clear();
            case "java" -> spec.javas.clear();
            case "profiles" -> spec.profiles.clear();
            case "policies" -> spec.policies.clear();
            case "engines" -> spec.engines.clear();
            case "memory" -> spec.memory.clear();
            case "particles" -> spec.particles.clear();
            case "datasets" -> spec.datasets.clear();
            case "load" -> spec.loads.clear();
            case "workload-arg" -> spec.workloadArgs.clear();
            default -> { }
        }
    }

    static void apply(MatrixSpec spec, String key, String value, String where) {
        String at = where.startsWith("--") ? where : where + ": " + key;
        switch (key) {
            case "runtimes" -> items(value, at).forEach(v -> spec.runtimes.add(new Sourced<>(v, at)));
            case "java" -> spec.javas.add(new Sourced<>(value.strip(), at));
            case "profiles" -> items(value, at).forEach(v -> spec.profiles.add(new Sourced<>(v, at)));
            case "policies" -> items(value, at).forEach(v -> {
                if (!MatrixDefaults.KNOWN_POLICIES.contains(v)) {
                    throw new BadUsageException(at + ": unknown policy '" + v + "' (known: "
                            + String.join(", ", MatrixDefaults.KNOWN_POLICIES) + ")");
                }
                spec.policies.add(new Sourced<>(v, at));
            });
            case "engines" -> items(value, at).forEach(v -> spec.engines.add(new Sourced<>(known(v, Engines.JVM_ENGINES, "engine", at), at)));
            case "memory" -> items(value, at).forEach(v -> spec.memory.add(new Sourced<>(known(v, Engines.MEMORY_STYLES, "memory style", at), at)));
            case "particles" -> items(value, at).forEach(v -> spec.particles.add(new Sourced<>(positiveInt(v, at), at)));
            case "datasets" -> items(value, at).forEach(v -> spec.datasets.add(new Sourced<>(v, at)));
            case "load" -> items(value, at).forEach(v -> {
                LoadScenario.parse(at, v);
                spec.loads.add(new Sourced<>(v, at));
            });
            case "workload-arg" -> spec.workloadArgs.add(new Sourced<>(value, at));
            case "repeat" -> {
                int r = positiveInt(value.strip(), at);
                // the plan holds every repetition (Integer.MAX_VALUE never ended planning): far past any run time
                if (r > MAX_REPEAT) {
                    throw new BadUsageException(at + ": '" + value.strip() + "' is more than " + MAX_REPEAT + " repetitions");
                }
                spec.repeat = r;
            }
            case "shard" -> spec.shard = shard(value.strip(), at);
            case "order-seed" -> spec.orderSeed = parseLong(value.strip(), at);
            case "seed" -> spec.seed = parseLong(value.strip(), at);
            case "timeout" -> spec.timeoutS = positiveDouble(value.strip(), at);
            case "time-scale" -> spec.timeScale = timeScale(value.strip(), at);
            case "load-alloc" -> {
                String[] f = value.strip().split(",", -1);
                if (f.length != 2) {
                    throw new BadUsageException(at + ": '" + value.strip() + "' must be MBPS,LIVEMB (e.g. 100,16)");
                }
                int live;
                try {
                    live = Integer.parseInt(f[1].strip());
                } catch (NumberFormatException e) {
                    live = -1;
                }
                if (live < 0) {
                    throw new BadUsageException(at + ": live set '" + f[1].strip() + "' must be an integer >= 0");
                }
                spec.loadSettings = new LoadSettings(LoadSettings.defaults().cpuWorkers(), positiveInt(f[0].strip(), at), live);
            }
            case "pin-cpu" -> {
                try {
                    if (CpuList.parse(value).isEmpty()) {
                        throw new IllegalArgumentException("empty");
                    }
                } catch (IllegalArgumentException e) {
                    throw new BadUsageException(at + ": '" + value + "' is not a CPU list like 1 or 2-3");
                }
                spec.pinCpu = value.strip();
            }
            case "db" -> spec.db = path(value.strip(), at);
            case "native" -> spec.nativeBinary = path(value.strip(), at);
            default -> throw new BadUsageException(where + ": unknown key '" + key + "' (known: " + String.join(", ", KEYS) + ")");
        }
    }

    /** A path, or bad usage (a NUL byte makes Path.of throw; found by MatrixFileFuzzTest). */
    private static Path path(String v, String at) {
        try {
            return Path.of(v);
        } catch (java.nio.file.InvalidPathException e) {
            throw new BadUsageException(at + ": '" + v.replace("\0", "\\x00") + "' is not a path");
        }
    }

    private static String known(String v, List<String> known, String what, String at) {
        if (!known.contains(v)) {
            throw new BadUsageException(at + ": unknown " + what + " '" + v + "' (known: " + String.join(", ", known) + ")");
        }
        return v;
    }

    private static List<String> items(String value, String at) {
        List<String> out = new java.util.ArrayList<>();
        for (String s : value.split(",", -1)) { // -1: a trailing empty item is one too
            String t = s.strip();
            if (t.isEmpty()) {
                throw new BadUsageException(at + ": empty item in '" + value + "'");
            }
            out.add(t);
        }
        return out;
    }

    private static int positiveInt(String v, String at) {
        try {
            int i = Integer.parseInt(v);
            if (i > 0) {
                return i;
            }
        } catch (NumberFormatException ignored) {
            // reported below
        }
        throw new BadUsageException(at + ": '" + v + "' is not a positive integer");
    }

    private static long parseLong(String v, String at) {
        try {
            return Long.parseLong(v);
        } catch (NumberFormatException e) {
            throw new BadUsageException(at + ": '" + v + "' is not an integer");
        }
    }

    /** The workload's range (RunOptions.TIME_SCALE_MIN/MAX): refused here, not by each run. */
    private static double timeScale(String v, String at) {
        double d = positiveDouble(v, at);
        if (d < 1e-6 || d > 1e3) {
            throw new BadUsageException(at + ": '" + v + "' is out of range [1e-6, 1000]");
        }
        return d;
    }

    private static double positiveDouble(String v, String at) {
        try {
            double d = Double.parseDouble(v);
            if (d > 0 && Double.isFinite(d)) {
                return d;
            }
        } catch (NumberFormatException ignored) {
            // reported below
        }
        throw new BadUsageException(at + ": '" + v + "' is not a positive number");
    }

    private static int[] shard(String v, String at) {
        String[] p = v.split("/");
        try {
            if (p.length == 2) {
                int k = Integer.parseInt(p[0].strip());
                int n = Integer.parseInt(p[1].strip());
                if (n >= 1 && k >= 1 && k <= n) {
                    return new int[] {k, n};
                }
            }
        } catch (NumberFormatException ignored) {
            // reported below
        }
        throw new BadUsageException(at + ": '" + v + "' is not a shard K/N with 1 <= K <= N");
    }
}
