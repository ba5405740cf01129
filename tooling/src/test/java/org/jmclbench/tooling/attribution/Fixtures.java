package org.jmclbench.tooling.attribution;

import java.net.URISyntaxException;
import java.nio.file.Path;
import java.util.List;

/** The recorded fixtures under src/test/resources/attribution (see recorder/record-fixtures.sh). */
final class Fixtures {
    /** JDKs with a JFR recording, a timenanos GC log, an uptime-only GC log (G1) and jobs. */
    static final List<String> JDKS = List.of("jdk11", "jdk17", "jdk21", "jdk25");
    /** JDKs with a ZGC log as well. */
    static final List<String> ZGC_JDKS = List.of("jdk17", "jdk21", "jdk25");
    /** The deliberately slow job of every fixture (40 ms of CPU for a 10 ms deadline). */
    static final int SLOW_JOB = 40;

    private Fixtures() {
    }

    static Path dir(String name) {
        try {
            return Path.of(Fixtures.class.getResource("/attribution/" + name).toURI());
        } catch (URISyntaxException e) {
            throw new IllegalStateException(e);
        }
    }
}
