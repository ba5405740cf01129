package org.jmclbench.tooling.runner;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

import org.jmclbench.tooling.runtime.LaunchPlan;
import org.jmclbench.tooling.runtime.ProcessRunner;
import org.jmclbench.tooling.runtime.RuntimeInfo;
import org.jmclbench.tooling.store.MachineInfo;
import org.jmclbench.tooling.store.StoreMerger;

/**
 * Trains the {@code aot} profile's cache once per JVM and flag set, on a short run of the workload
 * with the run's own policy (100 particles, the dataset replayed 10x faster, so that the classes
 * of that release engine are in the cache): JDK 25+ an AOT cache ({@code -XX:AOTCacheOutput},
 * then {@code -XX:AOTCache} with {@code -XX:AOTMode=on} so that an unusable cache fails loudly),
 * JDK 13-24 a dynamic AppCDS archive ({@code -XX:ArchiveClassesAtExit}, then {@code -XX:SharedArchiveFile}).
 * Caches live in {@code <db dir>/aot/}; a training the runtime refuses makes the profile unsupported, one
 * that crashes or hangs fails the run it trained for (and the next run trains again).
 */
final class AotTrainer {

    /**
     * The JVM flags that use the trained cache, or why there is none: {@code unsupported}, the runtime
     * cannot make one (too old, refused the flags, wrote no cache); {@code failed}, its training run
     * crashed or hung, a failure of the runtime under test as any run's would be.
     */
    record Result(List<String> flags, String unsupported, String failed) {
        Result(List<String> flags, String unsupported) {
            this(flags, unsupported, null);
        }
    }

    private final Path dir;
    private final Path home;
    private final Path jar;
    private final Map<String, Result> done = new HashMap<>();

    AotTrainer(Path dir, Path home, Path jar) {
        this.dir = dir;
        this.home = home;
        this.jar = jar;
    }

    Result ensure(RuntimeInfo rt, LaunchPlan plan, Dataset dataset, String policy) {
        String id = rt.name() + "-" + policy + "-" + MachineInfo.sha256Hex(rt.realPath() + "\n" + rt.version() + "\n"
                + String.join(" ", plan.jvmFlags())).substring(0, 12);
        Result r = done.get(id);
        if (r == null) {
            r = train(id, rt, plan, dataset, policy);
            if (r.failed() == null) {
                done.put(id, r); // a crash or hang is one run's failure: the next run trains again
            }
        }
        return r;
    }

    private Result train(String id, RuntimeInfo rt, LaunchPlan plan, Dataset dataset, String policy) {
        boolean aotCache = rt.major() >= 25;
        if (rt.major() < 13) {
            return new Result(List.of(), "aot: needs JDK 13+ (AppCDS dynamic archive) or 25+ (AOT cache)");
        }
        Path cache = dir.resolve(id + (aotCache ? ".aot" : ".jsa"));
        List<String> use = aotCache ? List.of("-XX:AOTCache=" + cache, "-XX:AOTMode=on")
                : List.of("-XX:SharedArchiveFile=" + cache);
        if (Files.isRegularFile(cache)) {
            return new Result(use, null);
        }
        Path work = null;
        try {
            Files.createDirectories(dir);
            work = Files.createTempDirectory(dir, id + ".training");
            Path partial = work.resolve(cache.getFileName());
            List<String> cmd = new ArrayList<>();
            cmd.add(rt.path().toString());
            cmd.addAll(plan.jvmFlags());
            cmd.add(aotCache ? "-XX:AOTCacheOutput=" + partial : "-XX:ArchiveClassesAtExit=" + partial);
            cmd.addAll(List.of("-Djmclbench.home=" + home, "-cp", jar.toString(), WorkloadCommand.MAIN_CLASS, "run",
                    "-p", "100", "-n", "1", "-j", "aot-training", "-O", work.resolve("out").toString(),
                    "--dataset", dataset.dir().toString()));
            if (policy.equals("ideal")) {
                cmd.add("--ideal");
            } else {
                cmd.addAll(List.of("--policy", policy, "--time-scale", "0.1"));
            }
            long timeoutMs = (long) ((dataset.durationS() * 0.1 * 3 + 120) * 1000);
            ProcessRunner.Result r;
            try {
                // the runner's shutdown hook kills the training as it kills a run (stopped, it ran on to its timeout),
                // and one started once the hook had run is killed at its start
                r = ProcessRunner.run(cmd, timeoutMs, ForkedRun::adopt);
            } finally {
                ForkedRun.CURRENT.set(null);
            }
            String interrupted = r.timedOut() ? null : ForkedRun.interruption(r.exitCode());
            if (interrupted != null) {
                // the runner is stopping (Ctrl-C reaches the training JVM too, in the runner's process
                // group): not a limit of the runtime, so no unsupported row; a training that ended
                // itself by a signal is the runtime's and fails below as any other
                throw new java.io.UncheckedIOException(new IOException("the AOT training run was interrupted (" + interrupted
                        + "); the run it trained for is not recorded: rerun the same command to resume"));
            }
            if (!r.ok() || !Files.isRegularFile(partial)) {
                String why = "aot: training run failed (" + (r.timedOut() ? "timed out" : ForkedRun.describeExit(r.exitCode(), ""))
                        + "): " + ProcessRunner.lastLine(r.output());
                boolean crashed = r.timedOut() || r.exitCode() > 128;
                return crashed ? new Result(List.of(), null, why) : new Result(List.of(), why);
            }
            Files.move(partial, cache, StandardCopyOption.ATOMIC_MOVE);
            return new Result(use, null);
        } catch (IOException e) {
            return new Result(List.of(), "aot: cannot train the cache: " + e.getMessage());
        } finally {
            if (work != null) {
                try {
                    StoreMerger.deleteTree(work);
                } catch (IOException ignored) {
                    // a leftover training folder is harmless
                }
            }
        }
    }
}
