package org.jmclbench.verification.jpf;

import java.io.IOException;
import java.io.Reader;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.Properties;

/**
 * A Java PathFinder build made by {@code verification/build-jpf.sh}: its folder and the JDK 17
 * that runs it (the java-17 branch's model classes fail on later JDKs).
 */
public record JpfHome(Path home, Path java) {

    /**
     * The JPF home from the system property {@code jpf.home}, else the environment variable
     * {@code JPF_HOME}, else {@code ~/.cache/jmclbench/jpf/current}; the java from
     * {@code jpf.java}, else the JDK the build recorded, else JDK 17 at its Debian path.
     */
    public static JpfHome locate() {
        String h = System.getProperty("jpf.home");
        if (h == null || h.isBlank()) {
            h = System.getenv("JPF_HOME");
        }
        Path home = h == null || h.isBlank()
                ? Paths.get(System.getProperty("user.home"), ".cache", "jmclbench", "jpf", "current")
                : Paths.get(h);
        if (!Files.isRegularFile(home.resolve("build/jpf.jar"))) {
            throw new IllegalStateException("no Java PathFinder build at " + home
                    + " (run verification/build-jpf.sh, or set -Djpf.home / JPF_HOME)");
        }
        String j = System.getProperty("jpf.java");
        if (j == null || j.isBlank()) {
            j = builtWith(home);
        }
        Path java = j == null ? Paths.get("/usr/lib/jvm/java-17-openjdk-amd64/bin/java") : Paths.get(j);
        if (!Files.isExecutable(java)) {
            throw new IllegalStateException("no JDK 17 java at " + java + " to run Java PathFinder (set -Djpf.java)");
        }
        return new JpfHome(home.toAbsolutePath(), java);
    }

    /** The java of the JDK that build-jpf.sh compiled with (BUILD-INFO's java= line), or null. */
    private static String builtWith(Path home) {
        Path info = home.resolve("BUILD-INFO");
        if (!Files.isRegularFile(info)) {
            return null;
        }
        Properties p = new Properties();
        try (Reader r = Files.newBufferedReader(info)) {
            p.load(r);
        } catch (IOException e) {
            return null;
        }
        String jdk = p.getProperty("java");
        return jdk == null ? null : jdk + "/bin/java";
    }

    /** jpf.jar: the model checker with its native peers (the host side). */
    public Path jpfJar() {
        return home.resolve("build/jpf.jar");
    }

    /** The site.properties that names this home, passed as {@code +site=}. */
    public Path siteProperties() {
        return home.resolve("site.properties");
    }
}
