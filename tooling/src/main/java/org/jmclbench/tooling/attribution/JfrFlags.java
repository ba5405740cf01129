package org.jmclbench.tooling.attribution;

import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.List;
import java.util.Optional;

/**
 * The JVM flags that capture a run's runtime events, for a Java feature version: a JFR
 * recording with our low-overhead settings ({@code jmclbench.jfc}) where the JVM has JFR
 * (JDK 11 and newer), else the GC log with the decorations {@link GcLogParser} places exactly.
 */
public final class JfrFlags {
    /** The recording's file name in the run directory. */
    public static final String RECORDING = "recording.jfr";
    /** The GC log's file name in the run directory (JVMs without JFR). */
    public static final String GC_LOG = "gc.log";
    /** Our JFR settings' file name in the run directory. */
    public static final String SETTINGS = "jmclbench.jfc";
    // the options forJava writes, each followed by a file of the run directory
    private static final String JFR_OPTION = "-XX:StartFlightRecording=filename=";
    private static final String GC_LOG_OPTION = "-Xlog:gc,gc+phases,safepoint:file=";
    private static final String LEGACY_GC_LOG_OPTION = "-Xloggc:";

    private JfrFlags() {
    }

    /** True when a JVM of this feature version has JDK Flight Recorder. */
    public static boolean hasJfr(int javaFeatureVersion) {
        return javaFeatureVersion >= 11;
    }

    /**
     * The capture for a JVM of {@code javaFeatureVersion} (8, 11, 17, ...) writing into
     * {@code runDir} (created if needed). For JFR this writes our settings file into the run
     * directory, so that the run folder says exactly what was recorded.
     *
     * @throws IllegalArgumentException when {@code runDir} holds a comma or an equals sign,
     *         which the JVM's {@code -XX:StartFlightRecording} option syntax cannot carry
     */
    public static EventCapture forJava(int javaFeatureVersion, Path runDir) {
        Path dir = runDir.toAbsolutePath().normalize();
        if (javaFeatureVersion >= 11) {
            if (dir.toString().contains(",") || dir.toString().contains("=")) {
                throw new IllegalArgumentException("run directory " + dir + ": a JFR file name cannot contain ',' or '='");
            }
            Path settings = dir.resolve(SETTINGS);
            Path recording = dir.resolve(RECORDING);
            writeSettings(settings);
            return new EventCapture(EventCapture.Mode.JFR, List.of(
                    JFR_OPTION + recording + ",settings=" + settings + ",dumponexit=true"),
                    recording);
        }
        Path log = dir.resolve(GC_LOG);
        if (javaFeatureVersion >= 9) {
            return new EventCapture(EventCapture.Mode.UNIFIED_GC_LOG, List.of(
                    GC_LOG_OPTION + log + ":uptime,timenanos,level,tags"), log);
        }
        if (javaFeatureVersion == 8) {
            return new EventCapture(EventCapture.Mode.LEGACY_GC_LOG, List.of("-verbose:gc", LEGACY_GC_LOG_OPTION + log,
                    "-XX:+PrintGCDetails", "-XX:+PrintGCDateStamps", "-XX:+PrintGCTimeStamps",
                    "-XX:+PrintGCApplicationStoppedTime"), log);
        }
        return new EventCapture(EventCapture.Mode.NONE, List.of(), null);
    }

    /**
     * The flag as a reader should see it: one that {@link #forJava} added, named without its
     * per-run file paths (they differ in every run and say nothing of the configuration); any
     * other flag as it is.
     */
    public static String withoutRunPaths(String jvmArg) {
        return captureName(jvmArg).orElse(jvmArg);
    }

    private static Optional<String> captureName(String a) {
        if (a.startsWith(JFR_OPTION) && a.contains("/" + RECORDING + ",settings=")
                && a.contains("/" + SETTINGS + ",")) {
            return Optional.of("-XX:StartFlightRecording (jmclbench's recording, for the causes of misses)");
        }
        if (a.startsWith(GC_LOG_OPTION) && a.contains("/" + GC_LOG + ":")) {
            return Optional.of("-Xlog:gc,gc+phases,safepoint (jmclbench's GC log, for the causes of misses)");
        }
        if (a.startsWith(LEGACY_GC_LOG_OPTION) && a.endsWith("/" + GC_LOG)) {
            return Optional.of("-Xloggc (jmclbench's GC log, for the causes of misses)");
        }
        return Optional.empty();
    }

    /** Copies our JFR settings to {@code target}. */
    public static void writeSettings(Path target) {
        try (InputStream in = JfrFlags.class.getResourceAsStream(SETTINGS)) {
            if (in == null) {
                throw new IllegalStateException("resource " + SETTINGS + " missing from the tooling jar");
            }
            Files.createDirectories(target.getParent());
            Files.copy(in, target, StandardCopyOption.REPLACE_EXISTING);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }
}
