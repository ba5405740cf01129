package org.jmclbench.verification.jpf;

import java.io.File;
import java.io.IOException;
import java.io.Reader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Properties;
import java.util.Set;
import java.util.TreeSet;
import java.util.concurrent.TimeUnit;

/**
 * Runs each {@link JpfCheck} in a forked JDK 17 JVM (the JVM flags JPF's model classes need,
 * a heap cap and a wall-clock limit as the check's budget) and reads the
 * {@link VerdictListener}'s file back into a {@link JpfResult}.
 */
public final class JpfRunner {
    /** What JPF's java-17 peers and model classes need opened on the host JVM. */
    public static final List<String> HOST_JVM_FLAGS = List.of(
            "--add-exports", "java.base/jdk.internal.misc=ALL-UNNAMED",
            "--add-opens", "java.base/jdk.internal.misc=ALL-UNNAMED",
            "--add-opens", "java.base/java.lang=ALL-UNNAMED",
            "--add-opens", "java.base/java.util=ALL-UNNAMED");

    /** A check's setting naming class folders put before the project's classes on the target's class path. */
    public static final String PREPEND = "jmclbench.classpath.prepend";

    private final JpfHome jpf;
    /** The project's classes and libraries: on the forked JVM's class path (listeners) and JPF's (the program). */
    private final List<String> classPath;
    private final Path logDir;
    private final int timeoutSeconds;
    private final int heapMegabytes;

    /**
     * @param jpf             the JPF build
     * @param classPath       the project's classes and their libraries (listeners and target programs)
     * @param logDir          where each run's console output is kept
     * @param timeoutSeconds  a check's wall-clock budget; a run still going then has failed
     * @param heapMegabytes   the forked JVM's heap cap
     */
    public JpfRunner(JpfHome jpf, List<String> classPath, Path logDir, int timeoutSeconds, int heapMegabytes) {
        this.jpf = jpf;
        List<String> cp = new ArrayList<>();
        for (String e : classPath) {
            String name = new File(e).getName();
            // JPF's own jars come from the home; never two copies on one path.
            if (!e.isEmpty() && !(name.startsWith("jpf") && name.endsWith(".jar"))) {
                // JPF runs in its own working directory: every entry absolute.
                cp.add(new File(e).getAbsolutePath());
            }
        }
        this.classPath = cp;
        this.logDir = logDir;
        this.timeoutSeconds = timeoutSeconds;
        this.heapMegabytes = heapMegabytes;
    }

    /** The class path of this JVM (the project's classes, as Maven or the launcher set it). */
    public static List<String> currentClassPath() {
        String cp = System.getProperty("java.class.path", "");
        return List.of(cp.split(File.pathSeparator));
    }

    /** Runs one check and judges its outcome against the check's expectation. */
    public JpfResult run(JpfCheck check) throws IOException, InterruptedException {
        Files.createDirectories(logDir);
        Path log = logDir.resolve(check.id() + ".log");
        Path verdict = logDir.resolve(check.id() + ".verdict");
        Files.deleteIfExists(verdict);
        Path work = Files.createTempDirectory("jmclbench-jpf-");
        List<String> cmd = command(check, verdict);
        long start = System.nanoTime();
        ProcessBuilder pb = new ProcessBuilder(cmd)
                // JPF looks for jpf.properties upward from its working directory: give it an empty one.
                .directory(work.toFile())
                .redirectErrorStream(true)
                .redirectOutput(log.toFile());
        Process p = pb.start();
        int budget = timeoutSeconds * check.budgetFactor();
        boolean finished = p.waitFor(budget, TimeUnit.SECONDS);
        if (!finished) {
            p.descendants().forEach(ProcessHandle::destroyForcibly);
            p.destroyForcibly();
            p.waitFor();
        }
        double seconds = (System.nanoTime() - start) / 1e9;
        keepAndDelete(work, check.id());
        Properties v = new Properties();
        if (Files.isRegularFile(verdict)) {
            try (Reader r = Files.newBufferedReader(verdict, StandardCharsets.UTF_8)) {
                v.load(r);
            }
        }
        return judge(check, v, finished, p.exitValue(), seconds, log);
    }

    /**
     * Deletes JPF's working directory, keeping what was left in it beside the log as
     * {@code ID.NAME}: a JVM that crashed wrote its hs_err_pid file there, and a directory that
     * was not empty failed the whole verify (DirectoryNotEmptyException), where the crash is that
     * check's failure.
     */
    private void keepAndDelete(Path work, String id) throws IOException {
        try (java.util.stream.Stream<Path> left = Files.list(work)) {
            for (Path f : (Iterable<Path>) left::iterator) {
                if (Files.isRegularFile(f)) {
                    Files.move(f, logDir.resolve(id + "." + f.getFileName()), StandardCopyOption.REPLACE_EXISTING);
                }
            }
        }
        try (java.util.stream.Stream<Path> tree = Files.walk(work)) {
            for (Path f : (Iterable<Path>) tree.sorted(java.util.Comparator.reverseOrder())::iterator) {
                Files.deleteIfExists(f);
            }
        }
    }

    /**
     * Why the forked JVM cannot start with this runner's flags (its heap cap), or null: one
     * {@code java ... -version} before any check, so that a heap no JVM can reserve is refused as
     * bad usage instead of failing every JPF check. The reason is the JVM's own last line, for
     * example "Could not reserve enough space for 2199023255552KB object heap".
     */
    public String unstartable() throws IOException, InterruptedException {
        List<String> cmd = jvm();
        cmd.add("-version");
        Process p = new ProcessBuilder(cmd).redirectErrorStream(true).start();
        List<String> lines = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8).lines()
                .filter(l -> !l.isBlank()).toList();
        if (p.waitFor() == 0) {
            return null;
        }
        return lines.isEmpty() ? "exit " + p.exitValue() : lines.get(lines.size() - 1).strip();
    }

    /** The forked JVM up to its class path: JDK 17, the heap cap, the collector and JPF's flags. */
    private List<String> jvm() {
        List<String> cmd = new ArrayList<>();
        cmd.add(jpf.java().toString());
        cmd.add("-Xmx" + heapMegabytes + "m");
        cmd.add("-XX:+UseSerialGC");
        cmd.addAll(HOST_JVM_FLAGS);
        return cmd;
    }

    /** The forked JVM's command line: JDK 17, JPF's flags, budgets, then JPF's own arguments. */
    List<String> command(JpfCheck check, Path verdict) {
        List<String> cmd = jvm();
        cmd.add("-cp");
        List<String> host = new ArrayList<>();
        host.add(jpf.jpfJar().toString());
        host.addAll(classPath);
        cmd.add(String.join(File.pathSeparator, host));
        cmd.add("gov.nasa.jpf.JPF");
        cmd.add("+site=" + jpf.siteProperties());
        Map<String, String> config = new LinkedHashMap<>(check.config());
        String listeners = VerdictListener.class.getName();
        if (config.containsKey("listener")) {
            listeners = listeners + "," + config.remove("listener");
        }
        cmd.add("+listener=" + listeners);
        cmd.add("+jmclbench.verdict=" + verdict.toAbsolutePath());
        // A seeded bug that is an edit of a shipped class puts the edited class first.
        String prepend = config.remove(PREPEND);
        cmd.add("+classpath=" + (prepend == null ? "" : prepend + ",") + String.join(",", classPath));
        for (Map.Entry<String, String> e : config.entrySet()) {
            cmd.add("+" + e.getKey() + "=" + e.getValue());
        }
        cmd.add(check.mainClass());
        cmd.addAll(check.args());
        return cmd;
    }

    private JpfResult judge(JpfCheck check, Properties v, boolean finished, int exit, double seconds, Path log)
            throws IOException {
        long newStates = longOf(v, "states.new");
        long endStates = longOf(v, "states.end");
        long maxDepth = longOf(v, "maxDepth");
        long insns = longOf(v, "instructions");
        int n = (int) longOf(v, "errors");
        List<String> errors = new ArrayList<>();
        for (int i = 0; i < n; i++) {
            errors.add(v.getProperty("error." + i + ".property") + ": " + v.getProperty("error." + i + ".message", ""));
        }
        String verdict;
        boolean passed = false;
        JpfResult.Failure failure;
        if (!finished) {
            verdict = "FAILED: over the " + timeoutSeconds * check.budgetFactor() + " s budget";
            failure = JpfResult.Failure.OVER_BUDGET;
        } else if (!"true".equals(v.getProperty("done"))) {
            verdict = "FAILED: JPF ended (exit " + exit + ") without a verdict: " + tail(log);
            failure = JpfResult.Failure.NO_VERDICT;
        } else if (v.getProperty("constraint") != null) {
            verdict = "FAILED: search limit hit (" + v.getProperty("constraint") + "), the state space was not covered";
            failure = JpfResult.Failure.SEARCH_LIMIT;
        } else if (check.expect().mustHold()) {
            Set<String> missing = new TreeSet<>(check.expect().coverage());
            missing.removeAll(List.of(v.getProperty("reached", "").split(",")));
            passed = n == 0 && missing.isEmpty();
            verdict = n > 0 ? "VIOLATED: " + shorten(errors.get(0))
                    : passed ? "holds" : "FAILED: vacuous, no path reached " + String.join(", ", missing);
            failure = passed ? null : n > 0 ? JpfResult.Failure.VIOLATION : JpfResult.Failure.VACUOUS;
        } else {
            JpfCheck.Expectation x = check.expect();
            String violates = v.getProperty("error.0.violates", "");
            List<String> at = List.of(v.getProperty("error.0.locations", "").split(","));
            passed = n == 1 && x.violated().name().equals(violates) && at.contains(x.location());
            verdict = passed ? "caught: " + violates + " at " + x.location()
                    : n == 0 ? "MISSED: the seeded bug went unreported"
                    : "MISSED: expected " + x.describe() + ", got " + (violates.isEmpty() ? "" : violates + " at ")
                            + String.join(" and ", at) + ": " + shorten(errors.get(0));
            failure = passed ? null : n == 0 ? JpfResult.Failure.MISSED : JpfResult.Failure.VIOLATION;
        }
        return new JpfResult(check, passed, verdict, errors, newStates, endStates, maxDepth, insns, seconds,
                log.toString(), failure);
    }

    private static long longOf(Properties p, String key) {
        String s = p.getProperty(key);
        return s == null ? 0 : Long.parseLong(s);
    }

    private static String shorten(String s) {
        return s.length() > 240 ? s.substring(0, 240) + "..." : s;
    }

    private static String tail(Path log) throws IOException {
        if (!Files.isRegularFile(log)) {
            return "(no output)";
        }
        List<String> lines = Files.readAllLines(log, StandardCharsets.UTF_8);
        return String.join(" | ", lines.subList(Math.max(0, lines.size() - 4), lines.size()));
    }
}
