package org.jmclbench.tooling.runner;

import org.jmclbench.tooling.store.StoredRuns;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.sql.SQLException;
import java.time.Instant;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.UUID;

import org.jmclbench.tooling.attribution.AttributionData;
import org.jmclbench.tooling.attribution.RunInstrumentation;
import org.jmclbench.tooling.cli.CodeVersion;
import org.jmclbench.tooling.runtime.HvmRuntime;
import org.jmclbench.tooling.runtime.IdleStateHold;
import org.jmclbench.tooling.runtime.RuntimeKind;
import org.jmclbench.tooling.runtime.LaunchPlan;
import org.jmclbench.tooling.runtime.ProfileComponent;
import org.jmclbench.tooling.runtime.ProfileProbe;
import org.jmclbench.tooling.store.MachineInfo;
import org.jmclbench.tooling.store.RunDetails;
import org.jmclbench.tooling.store.RunFolderIngest;
import org.jmclbench.tooling.store.RunRecorder;
import org.jmclbench.tooling.store.RunRow;
import org.jmclbench.tooling.store.StoreMerger;

import com.fasterxml.jackson.databind.ObjectMapper;

/**
 * Executes the runs of a resolved matrix one after another (never two at once: they would disturb
 * each other's timing), skipping those the store already holds with a final status, and commits
 * each run in one transaction as soon as it ends.
 */
public final class MatrixRunner {

    /** What this invocation did. */
    public record Summary(int planned, int alreadyDone, int ran, int ok, int failed, int timedOut, int unsupported,
                          List<String> problems) {
    }

    private static final ObjectMapper JSON = new ObjectMapper();

    private final ResolvedMatrix matrix;
    private final RunRecorder store;
    private final MachineInfo machine;
    private final String matrixId = UUID.randomUUID().toString();
    private final Path home;
    private final Path jar;
    private final ProfileProbe probe = ProfileProbe.withUserCache();

    private MatrixRunner(ResolvedMatrix matrix, RunRecorder store, MachineInfo machine, Path home, Path jar) {
        this.matrix = matrix;
        this.store = store;
        this.machine = machine;
        this.home = home;
        this.jar = jar;
    }

    /**
     * Records a new matrix of {@code matrix}'s runs in {@code store} (a fresh id, the command that
     * asked for it, the order seed and the resolved settings) and gives the runner of its runs.
     */
    public static MatrixRunner begin(ResolvedMatrix matrix, RunRecorder store, MachineInfo machine, String command,
                                     Path home, Path jar) throws SQLException, IOException {
        MatrixRunner r = new MatrixRunner(matrix, store, machine, home, jar);
        store.saveMatrix(r.matrixId, machine.machineId(), command, matrix.orderSeed(), Instant.now().toString(),
                MatrixSession.specJson(matrix));
        return r;
    }

    /** The matrix's id in the store. */
    public String matrixId() {
        return matrixId;
    }

    /** The runs still to do: not in the store, or failed/timed out when {@code retryFailed}. */
    public List<PlannedRun> remaining(boolean retryFailed) throws SQLException {
        Map<String, String> status = store.runStatuses();
        List<PlannedRun> todo = new ArrayList<>();
        for (PlannedRun r : matrix.plan()) {
            String s = status.get(r.runKey());
            if (s == null || retryFailed && (s.equals(RunRow.FAILED) || s.equals(RunRow.TIMEOUT))) {
                todo.add(r);
            }
        }
        return todo;
    }

    public Summary run(List<PlannedRun> todo, Progress progress) throws SQLException, IOException {
        AotTrainer aot = new AotTrainer(store.baseDir().resolve("aot"), home, jar);
        int ok = 0;
        int failed = 0;
        int timedOut = 0;
        int unsupported = 0;
        List<String> problems = new ArrayList<>();
        progress.start(todo.size());
        for (PlannedRun run : todo) {
            progress.started(run);
            Finished f = execute(run, aot);
            RunRow rec = f.record();
            try {
                store.saveRun(rec, f.data());
            } catch (SQLException e) {
                // rolled back: the store holds every run before this one and nothing of it
                throw new SQLException("--db: " + store.dbFile() + ": cannot record " + run.label() + " ("
                        + e.getMessage() + "); the runs recorded before it are kept: rerun the same command to resume", e);
            }
            switch (rec.status()) {
                case RunRow.OK -> ok++;
                case RunRow.TIMEOUT -> timedOut++;
                case RunRow.UNSUPPORTED -> unsupported++;
                default -> failed++;
            }
            if (!rec.status().equals(RunRow.OK)) {
                problems.add(String.format("%-11s %s: %s%s", rec.status(), run.label(), rec.failure(),
                        rec.runDir() == null ? "" : " [" + store.baseDir().resolve(rec.runDir()) + "]"));
            }
            progress.ended(run, rec.status(), rec.wallS() == null ? 0 : rec.wallS(), rec.failure());
        }
        progress.finish();
        return new Summary(matrix.plan().size(), matrix.plan().size() - todo.size(), todo.size(), ok, failed, timedOut,
                unsupported, problems);
    }

    /** A run's row and what the store keeps beside it. */
    private record Finished(RunRow record, RunDetails data) {
    }

    private Finished execute(PlannedRun run, AotTrainer aot) throws IOException {
        String startedAt = Instant.now().toString();
        String engineProblem = Engines.unsupported(run.engine(), run.memory());
        if (engineProblem != null) {
            return new Finished(record(run, RunRow.UNSUPPORTED, null, engineProblem, null, startedAt, null, null, null,
                    List.of()), RunDetails.empty());
        }
        ProfileProbe.Support support = probe.check(run.runtime(), run.profile(), matrix.pinCpu());
        LaunchPlan plan = LaunchPlan.of(run.runtime(), run.profile(), matrix.pinCpu());
        List<String> extra = List.of();
        if (support.supported() && run.runtime().isJvm() && run.profile().has(ProfileComponent.AOT)) {
            AotTrainer.Result a = aot.ensure(run.runtime(), plan, run.dataset(), run.policy());
            if (a.failed() != null) {
                return new Finished(record(run, RunRow.FAILED, null, a.failed(), null, startedAt, null, null, null,
                        List.of()), RunDetails.empty());
            }
            if (a.unsupported() != null) {
                support = ProfileProbe.Support.no(a.unsupported());
            }
            extra = a.flags();
        }
        Path folder = store.runFolder(run.runKey());
        // a folder without a row is the remains of a runner killed mid-run: start it afresh
        ForkedRun.killOrphan(folder);
        StoreMerger.deleteTree(folder);
        String loadProblem = RunInstrumentation.unsupported(run.runtime().isJvm() && Engines.JAVASE.equals(run.engine()),
                run.load());
        if (support.supported() && loadProblem != null) {
            support = ProfileProbe.Support.no(loadProblem);
        }
        if (!support.supported()) {
            return new Finished(record(run, RunRow.UNSUPPORTED, null, support.reason(), null, startedAt, null, null,
                    null, List.of()), RunDetails.empty());
        }
        IdleStateHold idle;
        try {
            idle = IdleStateHold.start(run.profile().has(ProfileComponent.NOIDLE), IdleStateHold.DEVICE);
        } catch (IOException e) { // the probe found the device writable; something took it away since
            return new Finished(record(run, RunRow.UNSUPPORTED, null, "noidle: " + e.getMessage(), null, startedAt,
                    null, null, null, List.of()), RunDetails.empty());
        }
        Files.createDirectories(folder);
        List<String> cmd;
        ForkOutcome o;
        // Event capture and load (docs/FORMATS.md sections 3 and 5): the load ends with the run, so do
        // the idle-state hold.
        try (idle; RunInstrumentation inst = RunInstrumentation.start(run.runtime().isJvm() ? run.runtime().major() : 0,
                run.load(), matrix.loadSettings(), folder, java.time.Duration.ofMillis((long) (matrix.timeoutFor(run) * 1000)))) {
            List<String> jvmFlags = new ArrayList<>(extra);
            jvmFlags.addAll(inst.jvmArgs());
            List<String> workloadArgs = new ArrayList<>(matrix.workloadArgs());
            workloadArgs.addAll(inst.workloadArgs());
            cmd = WorkloadCommand.build(run, plan, jvmFlags, home, jar, folder, matrix.timeScale(), workloadArgs);
            Map<String, String> env = new java.util.HashMap<>(Map.of("JMCLBENCH_HOME", home.toString()));
            if (run.runtime().kind() == RuntimeKind.HVM) {
                env.putAll(HvmRuntime.environment(run.profile()));
            }
            o = ForkedRun.execute(cmd, folder, folder, matrix.timeoutFor(run), env);
        }
        String status = o.status();
        String failure = o.failure();
        RunDetails data = RunDetails.empty();
        if (status.equals(RunRow.OK)) {
            String mismatch = describesAnotherRun(o.summary(), run);
            if (mismatch != null) {
                status = RunRow.FAILED;
                failure = "garbage output: summary.json describes another run (" + mismatch + ")";
            }
        }
        if (status.equals(RunRow.OK)) {
            try {
                data = RunFolderIngest.ingest(o.leaf(), o.summary(), run.dataset().dir().resolve("real.txt"));
            } catch (IOException | RuntimeException e) {
                status = RunRow.FAILED;
                failure = "garbage output: " + e.getMessage();
                data = RunDetails.empty();
            }
        }
        if (status.equals(RunRow.OK)) {
            try {
                AttributionData a = RunInstrumentation.attribute(o.leaf());
                for (org.jmclbench.tooling.attribution.MetricRow m : a.metrics()) {
                    if (Double.isFinite(m.value())) {
                        data.metrics.add(new RunDetails.Metric(m.task(), m.metric(), m.stat(), m.value()));
                    }
                }
                data.series.add(new RunDetails.Series("pauses", a.pauses()));
                data.attributions.addAll(a.rows());
            } catch (IOException | RuntimeException e) {
                // The run stands on its own; only its attribution is missing (explain says why).
                System.err.println("jmclbench: " + run.label() + ": no attribution: " + e.getMessage());
            }
        }
        Path dir = o.leaf() != null ? o.leaf() : folder;
        return new Finished(record(run, status, o.exitCode(), failure, o.stderrTail(), startedAt, o.wallS(),
                store.baseDir().relativize(dir).toString(), status.equals(RunRow.OK) ? o.summaryText() : null, cmd), data);
    }

    /**
     * What in the summary's parameters contradicts the run asked for (null when it matches), so
     * that a workload that ignored an option cannot report a result for it.
     */
    static String describesAnotherRun(com.fasterxml.jackson.databind.JsonNode summary, PlannedRun run) {
        com.fasterxml.jackson.databind.JsonNode p = summary.path("parameters");
        if (p.path("particles").asLong(-1) != run.particles()) {
            return "particles " + p.path("particles").asText("missing") + ", asked " + run.particles();
        }
        boolean ideal = run.policy().equals("ideal");
        if (ideal != p.path("ideal").asBoolean(false)) {
            return "ideal " + p.path("ideal").asText("missing") + ", asked policy " + run.policy();
        }
        if (!ideal && !run.policy().equals(p.path("policy").asText())) {
            return "policy " + p.path("policy").asText("missing") + ", asked " + run.policy();
        }
        if (p.has("seed") && p.path("seed").asLong() != run.seed()) {
            return "seed " + p.path("seed").asText() + ", asked " + run.seed();
        }
        // A summary without an engine is from a workload older than the engines: javase or native.
        String engine = StoredRuns.engineOf(p, summary.path("engine").path("kind").asText(""));
        if (engine.isEmpty() ? run.engine().equals(Engines.SCJ) : !engine.equals(run.engine())) {
            return "engine " + (engine.isEmpty() ? "missing" : engine) + ", asked " + run.engine();
        }
        if (p.hasNonNull("memory") && !p.path("memory").asText().equals(run.memory())) {
            return "memory " + p.path("memory").asText() + ", asked " + run.memory();
        }
        String mode = summary.path("engine").path("mode").asText("");
        if (run.runtime().kind() == RuntimeKind.HVM && !mode.equals(run.profile().hvmMode())) {
            return "hvm mode " + (mode.isEmpty() ? "missing" : mode) + ", asked " + run.profile().hvmMode();
        }
        return null;
    }

    private RunRow record(PlannedRun run, String status, Integer exitCode, String failure, String stderrTail,
                             String startedAt, Double wallS, String runDir, String summary, List<String> cmd) {
        String cmdJson;
        try {
            cmdJson = JSON.writeValueAsString(cmd);
        } catch (IOException e) {
            cmdJson = null;
        }
        return new RunRow(run.runKey(), matrixId, machine.machineId(), run.runtime().name(), run.runtime().version(),
                run.profile().name(), run.policy(), run.particles(), run.dataset().label(), run.load().label(), run.repetition(), status,
                exitCode, failure, stderrTail, startedAt, Instant.now().toString(), wallS, runDir, summary, run.seed(), cmdJson,
                run.engine(), run.memory(), CodeVersion.current());
    }
}
