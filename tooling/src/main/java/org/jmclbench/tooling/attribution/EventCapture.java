package org.jmclbench.tooling.attribution;

import java.nio.file.Path;
import java.util.List;

/**
 * How the runtime's events of one run are captured: the JVM flags the runner adds, and the
 * file they produce (read after the run by {@link JfrEventReader} or {@link GcLogParser}).
 *
 * @param mode    {@link Mode#JFR}, {@link Mode#UNIFIED_GC_LOG}, {@link Mode#LEGACY_GC_LOG} or {@link Mode#NONE}
 * @param jvmArgs the flags, one argument each
 * @param file    the recording or log the JVM will write, or null for {@link Mode#NONE}
 */
public record EventCapture(Mode mode, List<String> jvmArgs, Path file) {

    /** What kind of capture a JVM supports. */
    public enum Mode {
        /** JDK Flight Recorder (JDK 11+). */
        JFR,
        /** Unified GC logging, {@code -Xlog} (JDK 9 and 10). */
        UNIFIED_GC_LOG,
        /** {@code -verbose:gc -Xloggc} (JDK 8). */
        LEGACY_GC_LOG,
        /** Nothing (unknown or older JVMs, the native runtime). */
        NONE
    }
}
