package org.jmclbench.verification.jpf;

import java.io.IOException;
import java.io.Reader;
import java.nio.ByteBuffer;
import java.nio.channels.SeekableByteChannel;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.List;
import java.util.Properties;

/**
 * A Java PathFinder build made by {@code verification/build-jpf.sh}: its folder and the JDK 17
 * that runs it (the java-17 branch's model classes fail on later JDKs).
 */
public record JpfHome(Path home, Path java) {

    /** What build-jpf.sh leaves in a home it built, each needed by a check (its {@code built} test). */
    static final List<String> BUILT = List.of("build/jpf.jar", "build/jpf-classes.jar", "site.properties");

    /**
     * No usable Java PathFinder: one line saying what is missing and how to get it; {@code given}
     * when it is a path the user gave (bad input, exit 2) rather than something not there (exit 1).
     */
    public static final class MissingException extends IllegalStateException {
        private static final long serialVersionUID = 1L;
        private final boolean given;

        MissingException(String message, boolean given) {
            super(message);
            this.given = given;
        }

        /** True when the path that names nothing usable was given by the user (-Djpf.home, JPF_HOME, -Djpf.java). */
        public boolean given() {
            return given;
        }
    }

    /**
     * The JPF home from the system property {@code jpf.home}, else the environment variable
     * {@code JPF_HOME}, else {@code ~/.cache/jmclbench/jpf/current}; the java from
     * {@code jpf.java}, else the JDK the build recorded, else JDK 17 at its Debian path.
     *
     * @throws MissingException before any check can run, when the home lacks a file of a build
     *         (so that no check fails for JPF's absence) or the java is not there
     */
    public static JpfHome locate() {
        String h = System.getProperty("jpf.home");
        String named = "-Djpf.home";
        if (h == null || h.isBlank()) {
            h = System.getenv("JPF_HOME");
            named = "JPF_HOME";
        }
        boolean given = h != null && !h.isBlank();
        Path home = given ? Paths.get(h)
                : Paths.get(System.getProperty("user.home"), ".cache", "jmclbench", "jpf", "current");
        String lacks = lacks(home);
        if (lacks != null) {
            String how = "verification/build-jpf.sh builds one (JPF_CORE_SRC: a jpf-core folder or tarball"
                    + " such as jpf-core-7ea25de.tar.gz; ./jmclbench verify runs it)";
            throw given ? new MissingException(named + "=" + h + ": no Java PathFinder build there (" + lacks + "); " + how, true)
                    : new MissingException("no Java PathFinder build at " + home + " (" + lacks + "): " + how
                            + ", or set -Djpf.home / JPF_HOME to one", false);
        }
        String j = System.getProperty("jpf.java");
        boolean javaGiven = j != null && !j.isBlank();
        if (!javaGiven) {
            j = builtWith(home);
        }
        Path java = j == null ? Paths.get("/usr/lib/jvm/java-17-openjdk-amd64/bin/java") : Paths.get(j);
        if (!Files.isExecutable(java)) {
            throw javaGiven ? new MissingException("-Djpf.java=" + j + ": no such executable java", true)
                    : new MissingException("no JDK 17 java at " + java + " to run Java PathFinder (set -Djpf.java to one,"
                            + " or rebuild with JPF_JAVA_HOME)", false);
        }
        return new JpfHome(home.toAbsolutePath(), java);
    }

    /** What of a build {@code home} lacks ("no such folder", "no build/jpf.jar"), or null. */
    static String lacks(Path home) {
        if (!Files.isDirectory(home)) {
            return Files.exists(home) ? "not a folder" : "no such folder";
        }
        for (String f : BUILT) {
            Path p = home.resolve(f);
            if (!Files.isRegularFile(p)) {
                return "no " + f;
            }
            if (f.endsWith(".jar") && !wholeJar(p)) {
                return f + " is not a whole jar";
            }
        }
        return null;
    }

    /**
     * Whether {@code jar} ends with the zip end record, as every jar the jar tool writes (no comment)
     * does: one cut short (a full disk, a copy killed midway) does not, as build-jpf.sh checks too.
     */
    static boolean wholeJar(Path jar) {
        try (SeekableByteChannel ch = Files.newByteChannel(jar)) {
            if (ch.size() < 22) {
                return false;
            }
            ByteBuffer end = ByteBuffer.allocate(4);
            ch.position(ch.size() - 22);
            while (end.hasRemaining() && ch.read(end) > 0) {
                // the four bytes of the record's signature
            }
            return end.position() == 4 && end.get(0) == 'P' && end.get(1) == 'K' && end.get(2) == 5 && end.get(3) == 6;
        } catch (IOException e) {
            return false;
        }
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
