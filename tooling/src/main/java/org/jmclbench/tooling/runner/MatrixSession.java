package org.jmclbench.tooling.runner;

import java.io.IOException;
import java.io.PrintStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.function.Supplier;

import org.jmclbench.tooling.cli.BadUsageException;
import org.jmclbench.tooling.cli.Counts;
import org.jmclbench.tooling.doctor.Doctor;
import org.jmclbench.tooling.runtime.JmclbenchPaths;
import org.jmclbench.tooling.runtime.Profile;
import org.jmclbench.tooling.runtime.RuntimeDiscovery;
import org.jmclbench.tooling.runtime.RuntimeInfo;
import org.jmclbench.tooling.store.MachineInfo;
import org.jmclbench.tooling.store.ResultsDatabase;
import org.jmclbench.tooling.store.RunRecorder;

import com.fasterxml.jackson.databind.ObjectMapper;

/**
 * One invocation of {@code matrix} or {@code quick}: resolve the spec (all bad input is found here,
 * before anything runs), open the database to write (which takes its lock), record the machine
 * (with the doctor's checks) and the invocation, run what is left, and print what failed.
 */
public final class MatrixSession {

    private MatrixSession() {
    }

    /** The result of a session: the exit code and, when it ran, the database. */
    public record Result(int exitCode, Path db) {
    }

    /**
     * @throws BadUsageException for bad input (nothing has run then)
     */
    public static Result execute(MatrixSpec spec, String commandText, PrintStream out,
                                 Supplier<RuntimeDiscovery> discovery) throws IOException, java.sql.SQLException {
        Path home = JmclbenchPaths.home();
        MachineInfo machine = MachineInfo.current();
        ResolvedMatrix m = MatrixPlanner.resolve(spec, discovery, home, machine);
        Path jar = JmclbenchPaths.workloadJar();
        boolean anyJvm = m.runtimes().stream().anyMatch(RuntimeInfo::isJvm);
        if (anyJvm && !Files.isRegularFile(jar)) {
            System.err.println("jmclbench: the workload jar is not built (" + jar + "): ./jmclbench build");
            return new Result(1, m.db());
        }
        if (spec.dryRun) {
            ResultsDatabase.checkToWrite(m.db(), "--db"); // what the run would refuse, the plan is refused for
            out.printf("%s planned%s, order seed %d:%n", Counts.of(m.plan().size(), "run"), shardText(m), m.orderSeed());
            for (PlannedRun r : m.plan()) {
                out.println("  " + r.runKey() + "  " + r.label());
            }
            return new Result(0, m.db());
        }
        MatrixPlanner.prepareHvm(spec, m, home); // before the store is touched: a build that fails records nothing
        try (RunRecorder store = RunRecorder.open(m.db(), "--db")) {
            store.saveMachine(machine, Doctor.toJson(Doctor.system().run()));
            MatrixRunner runner = MatrixRunner.begin(m, store, machine, commandText, home, jar);
            List<PlannedRun> todo = runner.remaining(spec.retryFailed);
            out.printf("matrix %s: %s%s, %d already in %s, %d to run (order seed %d)%n", runner.matrixId().substring(0, 8),
                    Counts.of(m.plan().size(), "run"), shardText(m), m.plan().size() - todo.size(), m.db(), todo.size(), m.orderSeed());
            out.flush();
            MatrixRunner.Summary s = runner.run(todo, Progress.forConsole(out));
            out.printf("matrix done: %d ran (%d ok, %d failed, %d timed out, %d unsupported); results in %s%n", s.ran(),
                    s.ok(), s.failed(), s.timedOut(), s.unsupported(), m.db());
            if (!s.problems().isEmpty()) {
                out.println("runs that did not succeed:");
                s.problems().forEach(p -> out.println("  " + p));
            }
            return new Result(0, m.db());
        }
    }

    private static String shardText(ResolvedMatrix m) {
        return m.shard() == null ? "" : " (shard " + m.shard()[0] + "/" + m.shard()[1] + " of " + m.planned() + ")";
    }

    static String specJson(ResolvedMatrix m) throws IOException {
        Map<String, Object> j = new LinkedHashMap<>();
        j.put("runtimes", m.runtimes().stream().map(r -> Map.of("name", r.name(), "kind", r.kind().name().toLowerCase(),
                "vendor", r.vendor(), "version", r.version(), "path", r.realPath().toString())).toList());
        j.put("profiles", m.profiles().stream().map(Profile::name).toList());
        j.put("engines", m.engines());
        j.put("memory", m.memory());
        j.put("policies", m.policies());
        j.put("particles", m.particles());
        j.put("loads", m.loads().stream().map(l -> l.label()).toList());
        j.put("loadAlloc", m.loadSettings().allocMbPerS() + "," + m.loadSettings().allocLiveMb());
        j.put("datasets", m.datasets().stream().map(d -> Map.of("label", d.label(), "path", d.dir().toString(),
                "digest", d.digest(), "durationS", d.durationS())).toList());
        j.put("repeat", m.repeat());
        j.put("seed", m.seed());
        j.put("orderSeed", m.orderSeed());
        j.put("timeScale", m.timeScale());
        j.put("timeoutS", m.timeoutS());
        j.put("pinCpu", m.pinCpu());
        j.put("workloadArgs", m.workloadArgs());
        j.put("shard", m.shard() == null ? null : m.shard()[0] + "/" + m.shard()[1]);
        j.put("planned", m.planned());
        j.put("thisShard", m.plan().size());
        return new ObjectMapper().writeValueAsString(j);
    }
}
