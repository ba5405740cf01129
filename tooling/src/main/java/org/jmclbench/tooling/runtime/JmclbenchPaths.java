package org.jmclbench.tooling.runtime;

import java.nio.file.Path;

/** Where the project lives and where the tool keeps its caches (installed JDKs, probe results). */
public final class JmclbenchPaths {
    private JmclbenchPaths() {
    }

    /** The project folder: {@code -Djmclbench.home} (set by the launcher), else the working folder. */
    public static Path home() {
        String h = System.getProperty("jmclbench.home");
        if (h == null || h.isEmpty()) {
            h = System.getenv("JMCLBENCH_HOME");
        }
        return Path.of(h == null || h.isEmpty() ? "." : h).toAbsolutePath().normalize();
    }

    /** {@code ${XDG_CACHE_HOME:-~/.cache}/jmclbench}, or {@code -Djmclbench.cache} (tests use that). */
    public static Path cache() {
        String c = System.getProperty("jmclbench.cache");
        if (c != null && !c.isEmpty()) {
            return Path.of(c).toAbsolutePath();
        }
        String xdg = System.getenv("XDG_CACHE_HOME");
        Path base = xdg != null && !xdg.isEmpty() ? Path.of(xdg) : Path.of(System.getProperty("user.home"), ".cache");
        return base.resolve("jmclbench").toAbsolutePath();
    }

    /** JDKs installed by {@code jmclbench jvm install}. */
    public static Path jdks() {
        return cache().resolve("jdks");
    }

    /** The HVM launcher's class path: the host side of the hvm engine, with the workload jar it runs through. */
    public static String hvmLauncherClassPath() {
        return home().resolve("hvm/launcher/target/jmclbench-hvm-launcher.jar") + java.io.File.pathSeparator + workloadJar();
    }

    /** The workload jar, run on every JVM under test. */
    public static Path workloadJar() {
        return home().resolve("workload/target/jmclbench-workload.jar");
    }

    /** The native C baseline, built by the launcher. */
    public static Path nativeBinary() {
        return home().resolve("native/build/jmclbench-native");
    }
}
