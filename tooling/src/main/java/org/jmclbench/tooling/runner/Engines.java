package org.jmclbench.tooling.runner;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.stream.Stream;

import org.jmclbench.tooling.runtime.RuntimeInfo;
import org.jmclbench.tooling.runtime.RuntimeKind;

/**
 * The workload's engines and the memory styles each one has (docs/FORMATS.md section 2): on a
 * JVM, {@code javase} (the Java SE release engine: heap, GC), {@code scj} (the SCJ mission:
 * immortal, mission and private memory), {@code rtsj} and {@code rtsj-atomic} (the thesis's RTSJ
 * program in its two designs, the workload's {@code --engine rtsj --rtsj-design thesis|atomic});
 * the native baseline is its own engine, {@code native}.
 */
public final class Engines {

    public static final String JAVASE = "javase";
    public static final String SCJ = "scj";
    public static final String NATIVE = "native";
    /** The RTSJ program, design thesis (the AIE deferred by the robot's monitor) and design atomic. */
    public static final String RTSJ = "rtsj";
    public static final String RTSJ_ATOMIC = "rtsj-atomic";
    /**
     * The engines a JVM runtime can run, for {@code --engines}: the workload's registry
     * ({@code org.jmclbench.workload.engine.Engines}), its rtsj engine as its two designs. The hvm
     * engine, when its launcher is on the class path, is a host of its own runtime
     * ({@link org.jmclbench.tooling.runtime.RuntimeKind#HVM}), not an engine of a JVM.
     */
    public static final List<String> JVM_ENGINES = jvmEngines(org.jmclbench.workload.engine.Engines.list());

    /** Every engine a stored run can have: the JVM ones, then each program that is its own engine ({@code native}, {@code hvm}). */
    public static final List<String> ALL = Stream.concat(JVM_ENGINES.stream(), Stream.of(RuntimeKind.values())
            .filter(k -> k != RuntimeKind.JVM).map(k -> k.name().toLowerCase(Locale.ROOT))).toList();

    public static final String PREALLOCATED = "preallocated";
    /** Every memory style some engine has, for {@code --memory}. */
    public static final List<String> MEMORY_STYLES = List.of(PREALLOCATED, "allocating", "scoped");

    private Engines() {
    }

    /** The matrix's engines of the workload's {@code --engine} values. */
    static List<String> jvmEngines(List<String> workloadEngines) {
        List<String> out = new ArrayList<>();
        for (String e : workloadEngines) {
            if (e.equals(RTSJ)) {
                out.addAll(List.of(RTSJ, RTSJ_ATOMIC));
            } else if (!e.equals(RuntimeKind.HVM.name().toLowerCase(Locale.ROOT))) {
                out.add(e);
            }
        }
        return List.copyOf(out);
    }

    /**
     * The engine a run of {@code runtime} gets when {@code asked} is the matrix's engine: a program
     * that is not a JVM is its own engine, named by its kind ({@code native}).
     */
    public static String of(RuntimeInfo runtime, String asked) {
        return runtime.isJvm() ? asked : runtime.kind().name().toLowerCase(Locale.ROOT);
    }

    /** The workload's options that choose an engine of a JVM runtime (none for javase, the default). */
    public static List<String> workloadArgs(String engine) {
        return switch (engine) {
            case JAVASE -> List.of();
            case RTSJ -> List.of("--engine", RTSJ, "--rtsj-design", "thesis");
            case RTSJ_ATOMIC -> List.of("--engine", RTSJ, "--rtsj-design", "atomic");
            default -> List.of("--engine", engine);
        };
    }

    /** What an engine's runs add to the runtime's name in the run path, as the workload's default does. */
    public static String runtimeSuffix(String engine) {
        return switch (engine) {
            case JAVASE, NATIVE -> "";
            case RTSJ -> "-rtsj-thesis";
            case RTSJ_ATOMIC -> "-rtsj-atomic";
            default -> "-" + engine;
        };
    }

    /** The memory styles of an engine; {@code preallocated} (the default) is every engine's. */
    public static List<String> memoryStyles(String engine) {
        return switch (engine) {
            case SCJ, "hvm" -> List.of(PREALLOCATED, "scoped"); // the SCJ mission, on the JVM or on an SCJ VM
            default -> List.of(PREALLOCATED, "allocating");
        };
    }

    /** Why a run of this engine and memory style cannot be made, or null when it can. */
    public static String unsupported(String engine, String memory) {
        List<String> styles = memoryStyles(engine);
        return styles.contains(memory) ? null
                : "engine " + engine + " has no memory style '" + memory + "' (it has " + String.join(", ", styles) + ")";
    }
}
