package org.jmclbench.tooling.attribution;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Real runs of the workload in a child JVM, captured with {@link JfrFlags}, then attributed.
 * Wide margins: each asserts only that at least one miss has the expected cause.
 */
class AttributionEndToEndTest {

    /** The first {@code seconds} of the shipped match-short dataset as thesis-format files. */
    private static List<String> shortData(Path dir, double seconds) throws IOException {
        Path src = Path.of(System.getProperty("user.dir")).getParent().resolve("data/match-short");
        List<String> args = new ArrayList<>();
        for (String[] f : new String[][] {{"odometry.txt", "-odo"}, {"laser.txt", "-laser"}, {"real.txt", "-real"}}) {
            List<String> kept = Files.readAllLines(src.resolve(f[0]), StandardCharsets.UTF_8).stream()
                    .filter(l -> l.isBlank() || l.startsWith("#") || Double.parseDouble(l.trim().split("\\s+")[0]) < seconds)
                    .toList();
            Path out = dir.resolve(f[0]);
            Files.write(out, kept, StandardCharsets.UTF_8);
            args.add(f[1]);
            args.add(out.toString());
        }
        return args;
    }

    private static RunEvidence run(Path root, List<String> jvmArgs, List<String> workloadArgs) throws Exception {
        Path runDir = root.resolve("runs/e2e");
        EventCapture capture = JfrFlags.forJava(Runtime.version().feature(), runDir);
        List<String> cmd = new ArrayList<>();
        cmd.add(ProcessHandle.current().info().command().orElse("java"));
        cmd.addAll(jvmArgs);
        cmd.addAll(capture.jvmArgs());
        cmd.addAll(List.of("-cp", System.getProperty("java.class.path"), "org.jmclbench.workload.WorkloadMain", "run",
                "-O", runDir.toString()));
        cmd.addAll(workloadArgs);
        Process p = new ProcessBuilder(cmd).redirectErrorStream(true).redirectOutput(root.resolve("out.txt").toFile()).start();
        boolean ended = p.waitFor(240, TimeUnit.SECONDS);
        if (!ended) {
            p.destroyForcibly();
        }
        String out = Files.readString(root.resolve("out.txt"));
        assertTrue(ended && p.exitValue() == 0, "the workload ran: " + out);
        assertTrue(Files.size(capture.file()) > 0, "the recording was written");
        return RunEvidence.load(runDir);
    }

    /**
     * Runs like this one miss 2 to 5 jobs in 10 s, so a run can miss none: that run is no evidence
     * either way and is repeated (up to three runs). A run with misses of which none overlaps a GC
     * pause fails at once.
     */
    @Test
    void underAllocationLoadOnASmallSerialHeapAMissIsAttributedToAGcPause(@TempDir Path tmp) throws Exception {
        List<String> args = new ArrayList<>(shortData(tmp, 16.0));
        args.addAll(List.of("-p", "1000", "--time-scale", "0.5", "--load-alloc", "300,28"));
        List<JobAttribution> a = List.of();
        for (int attempt = 1; attempt <= 3 && a.isEmpty(); attempt++) {
            Path root = Files.createDirectories(tmp.resolve("attempt-" + attempt));
            RunEvidence run = run(root, List.of("-XX:+UseSerialGC", "-Xmx48m", "-Xms48m"), args);
            assertTrue(run.eventSource().startsWith("JFR "), run.eventSource());
            assertEquals("alloc", run.summary().path("parameters").path("load").path("scenario").asText());
            // the Serial collector's pauses in the run (only those are kept: a young one at start-up is not)
            assertTrue(run.events().stream().anyMatch(e -> e.kind() == VmEventKind.GC_PAUSE
                    && (e.detail().startsWith("DefNew") || e.detail().startsWith("SerialOld"))), run.eventSource());
            a = run.attribute(Attribution.Settings.defaults());
        }
        List<JobAttribution> missed = a;
        assertTrue(missed.stream().anyMatch(j -> j.causes().stream().anyMatch(c -> c.kind().equals("gc"))),
                "some miss overlaps a GC pause; causes: " + Attribution.countCauses(missed));
    }

    @Test
    void aJobThatCannotFitItsDeadlineIsAttributedToCompute(@TempDir Path tmp) throws Exception {
        List<String> args = new ArrayList<>(shortData(tmp, 3.0));
        args.addAll(List.of("-p", "300000"));
        RunEvidence run = run(tmp, List.of("-Xmx512m"), args);
        List<JobAttribution> a = run.attribute(Attribution.Settings.defaults());
        // Among its causes, not necessarily the largest: on a busy machine preemption can outweigh it.
        assertTrue(a.stream().anyMatch(j -> j.causes().stream().anyMatch(c -> c.kind().equals("compute"))),
                "300,000 particles cannot be predicted within 50 ms; causes: " + Attribution.countCauses(a));
    }

    /**
     * The same overload on the rtsj engine: its jobs carry their CPU time now (through the shim's
     * clock on a JVM), so a miss is told as compute there too, not only as overlap or os.
     */
    @Test
    void anRtsjJobThatCannotFitItsDeadlineIsAttributedToCompute(@TempDir Path tmp) throws Exception {
        List<String> args = new ArrayList<>(shortData(tmp, 3.0));
        args.addAll(List.of("-p", "300000", "--engine", "rtsj"));
        RunEvidence run = run(tmp, List.of("-Xmx512m"), args);
        assertEquals("rtsj", run.summary().path("engine").path("kind").asText());
        List<JobAttribution> a = run.attribute(Attribution.Settings.defaults());
        assertTrue(a.stream().anyMatch(j -> j.causes().stream().anyMatch(c -> c.kind().equals("compute"))),
                "300,000 particles cannot be predicted within 50 ms; causes: " + Attribution.countCauses(a));
    }
}
