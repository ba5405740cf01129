package org.jmclbench.tooling;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.InputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;

import org.jmclbench.tooling.cli.JmclbenchCli;

/** Test fixtures: a project home with a tiny dataset, fake runtimes, and a CLI call that captures output. */
public final class Fixtures {

    private Fixtures() {
    }

    /** A project home with {@code data/tiny} (1 s) and a stand-in workload jar; sets the system properties. */
    /** The project's folder (the one holding data/README.md), found above the working directory. */
    public static Path projectHome() {
        Path p = Path.of("").toAbsolutePath();
        while (p != null && !Files.isRegularFile(p.resolve("data/README.md"))) {
            p = p.getParent();
        }
        if (p == null) {
            throw new IllegalStateException("data/README.md not found above " + Path.of("").toAbsolutePath());
        }
        return p;
    }

    public static Path home(Path dir) throws IOException {
        Path ds = dir.resolve("data/tiny");
        Files.createDirectories(ds);
        StringBuilder odo = new StringBuilder();
        StringBuilder real = new StringBuilder();
        for (int i = 0; i < 20; i++) {
            odo.append(String.format(java.util.Locale.ROOT, "%.16e  %.16e  %.16e  %.16e%n", i * 0.05, 0.001, 0.0, 0.0));
            real.append(String.format(java.util.Locale.ROOT, "%.16e  %.16e  %.16e  %.16e%n", i * 0.05, 0.4 + i * 0.001, 0.4, 0.0));
        }
        Files.writeString(ds.resolve("odometry.txt"), odo);
        Files.writeString(ds.resolve("real.txt"), real);
        Files.writeString(ds.resolve("laser.txt"), "1.0e-01  1.0e+00\n5.0e-01  2.0e+00\n");
        Files.writeString(ds.resolve("dataset.properties"), "format=jmclbench-dataset/1\nduration=1.0\n");
        Path jar = dir.resolve("workload/target/jmclbench-workload.jar");
        Files.createDirectories(jar.getParent());
        Files.writeString(jar, "stand-in: the fake runtimes never read it");
        System.setProperty("jmclbench.home", dir.toString());
        System.setProperty("jmclbench.cache", dir.resolve("cache").toString());
        return dir;
    }

    /** A fake {@code java} doing {@code mode} after {@code sleepS} seconds; {@code reject} is a flag it refuses. */
    public static Path fakeJava(Path dir, String name, String mode, double sleepS, String reject, int major) throws IOException {
        String script;
        try (InputStream in = Fixtures.class.getResourceAsStream("fake-java.sh")) {
            script = new String(in.readAllBytes(), StandardCharsets.UTF_8);
        }
        script = script.replace("@MODE@", mode).replace("@SLEEP@", String.valueOf(sleepS))
                .replace("@REJECT@", reject == null ? "" : reject).replace("@MAJOR@", String.valueOf(major))
                .replace("@HANGMARK@", hangMark(dir));
        Path bin = dir.resolve(name).resolve("bin");
        Files.createDirectories(bin);
        Path java = bin.resolve("java");
        Files.writeString(java, script);
        Files.setPosixFilePermissions(java, PosixFilePermissions.fromString("rwxr-xr-x"));
        return java;
    }

    /**
     * The fake runtimes of tests that fill a store with runs that succeed and runs that fail, in
     * folders a, b and crash of {@code dir}: Java 17 and 21 that run, and a Java 11 that crashes.
     */
    public record FakeJvms(String java17, String java21, String crashing11) {
        public static FakeJvms in(Path dir) throws IOException {
            return new FakeJvms(fakeJava(dir, "a", "ok", 0, null, 17).toString(), fakeJava(dir, "b", "ok", 0, null, 21).toString(),
                    fakeJava(dir, "crash", "crash", 0, null, 11).toString());
        }
    }

    /** A sleep length unique to this test folder, so that a test can find a leftover hung process. */
    public static String hangMark(Path dir) {
        return "1000." + Math.abs(dir.toString().hashCode());
    }

    /**
     * The command that runs the CLI with {@code args} in a child JVM of the test's class path, on the home
     * {@code dir}: for tests that kill the runner or run two at once.
     */
    public static java.util.List<String> childCli(Path dir, String... args) {
        java.util.List<String> cmd = new java.util.ArrayList<>(java.util.List.of(
                ProcessHandle.current().info().command().orElse("java"),
                "-Djmclbench.home=" + dir, "-Djmclbench.cache=" + dir.resolve("cache"),
                "-cp", System.getProperty("java.class.path"), JmclbenchCli.class.getName()));
        cmd.addAll(java.util.List.of(args));
        return cmd;
    }

    /** What a CLI call printed and returned. */
    public record CliResult(int exitCode, String out, String err) {
    }

    /** Runs the CLI in this JVM, capturing stdout and stderr. */
    public static synchronized CliResult cli(String... args) {
        PrintStream oldOut = System.out;
        PrintStream oldErr = System.err;
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        try {
            System.setOut(new PrintStream(out, true, StandardCharsets.UTF_8));
            System.setErr(new PrintStream(err, true, StandardCharsets.UTF_8));
            int rc = JmclbenchCli.execute(args);
            return new CliResult(rc, out.toString(StandardCharsets.UTF_8), withoutFuzzerLines(err.toString(StandardCharsets.UTF_8)));
        } finally {
            System.setOut(oldOut);
            System.setErr(oldErr);
        }
    }

    /**
     * {@code err} without the lines Jazzer's agent prints when it instruments a class: once
     * MatrixFileFuzzTest has run in this test JVM, the first use of a class (say a new record of the
     * evaluation matrix) adds "INFO: Instrumented ... with custom hooks only" to whatever stderr is
     * then, which is the test JVM's, not the command's.
     */
    static String withoutFuzzerLines(String err) {
        return err.replaceAll("(?m)^INFO: Instrumented [^\n]*\n", "");
    }

    /**
     * How many of process {@code pid}'s file descriptors ({@code "self"}: this JVM's) point at {@code file}, read from
     * Linux's /proc/PID/fd; 0 once the process has ended.
     */
    public static long openDescriptors(String pid, Path file) throws IOException {
        Path real = file.toRealPath();
        try (java.util.stream.Stream<Path> fds = Files.list(Path.of("/proc", pid, "fd"))) {
            return fds.filter(fd -> {
                try {
                    return Files.readSymbolicLink(fd).equals(real);
                } catch (IOException e) {
                    return false; // closed meanwhile, or the listing's own descriptor
                }
            }).count();
        } catch (java.nio.file.NoSuchFileException e) {
            return 0; // the process ended
        }
    }

    /** The first column of each row of {@code sql} on the SQLite file {@code db}, mapped to its second. */
    public static java.util.Map<String, String> columns(Path db, String sql) throws java.sql.SQLException {
        java.util.Map<String, String> m = new java.util.HashMap<>();
        try (java.sql.Connection c = java.sql.DriverManager.getConnection("jdbc:sqlite:" + db);
             java.sql.Statement s = c.createStatement();
             java.sql.ResultSet rs = s.executeQuery(sql)) {
            while (rs.next()) {
                m.put(rs.getString(1), rs.getString(2));
            }
        }
        return m;
    }
}
